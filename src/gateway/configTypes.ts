// Types and the error shared by the config schema (config.ts) and the address map (pointMap.ts).
import type { PointType } from '../protocol/points';

export const MODBUS_TABLES = ['coils', 'discreteInputs', 'inputRegisters', 'holdingRegisters'] as const;
export type ModbusTable = (typeof MODBUS_TABLES)[number];

/** One entry of a device's `points` list (docs/GATEWAY-CONFIG.md). */
export interface PointEntry {
  readonly address: string;
  readonly count: number;
  readonly table?: ModbusTable;
  readonly register?: number;
  readonly type?: PointType;
  readonly hold: boolean;
}

/** A config mistake, located: `gateway.json: devices[0].points[2]: ...`. */
export class ConfigError extends Error {
  constructor(
    readonly where: string,
    message: string,
  ) {
    super(`${where}: ${message}`);
    this.name = 'ConfigError';
  }
}
