// Groups a device's points into the few Modbus requests that read or write them.
import type { PointType, WireValue } from '../protocol/points';
import type { ModbusTable } from './configTypes';
import type { DevicePoint } from './pointMap';

export interface RequestBlock {
  readonly table: ModbusTable;
  readonly start: number;
  /** Points in register order; index i sits at register start + i. */
  readonly points: readonly DevicePoint[];
}

/** Modbus limits per request (read coils 2000, write coils 1968, read registers 125, write registers 123). */
const maxLength = (table: ModbusTable, write: boolean) =>
  table === 'coils' || table === 'discreteInputs' ? (write ? 1968 : 2000) : write ? 123 : 125;

/** Contiguous runs of registers per table, split at the protocol's size limits. */
export function planBlocks(points: readonly DevicePoint[], write: boolean): RequestBlock[] {
  const blocks: RequestBlock[] = [];
  const byTable = new Map<ModbusTable, DevicePoint[]>();
  for (const p of points) byTable.set(p.table, [...(byTable.get(p.table) ?? []), p]);
  for (const [table, list] of byTable) {
    const sorted = [...list].sort((a, b) => a.register - b.register);
    let run: DevicePoint[] = [];
    const flush = () => {
      if (run.length && run[0]) blocks.push({ table, start: run[0].register, points: run });
      run = [];
    };
    for (const p of sorted) {
      const last = run[run.length - 1];
      if (last && (p.register !== last.register + 1 || run.length >= maxLength(table, write))) flush();
      run.push(p);
    }
    flush();
  }
  return blocks;
}

/** Raw 16-bit register -> wire value of the point's type. */
export function fromRegister(type: PointType, raw: number): WireValue {
  const u = raw & 0xffff;
  if (type === 'BOOL') return u !== 0;
  return type === 'INT' && u >= 0x8000 ? u - 0x10000 : u;
}

/** Wire value -> raw 16-bit register. */
export function toRegister(value: WireValue): number {
  if (typeof value === 'boolean') return value ? 1 : 0;
  return value & 0xffff;
}
