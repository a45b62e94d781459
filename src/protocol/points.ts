// I/O points as the gateway exposes them: IEC address, wire type, direction, owning device.
import { parseLocation } from '../model/iecTypes';

/** Types a gateway point can carry on the wire. Registers are 16 bit. */
export const POINT_TYPES = ['BOOL', 'WORD', 'INT', 'UINT'] as const;
export type PointType = (typeof POINT_TYPES)[number];

export type PointDir = 'in' | 'out';
/** `stale`: the device is offline and the value is the last one read, not a live one. */
export type Quality = 'good' | 'stale';
/** BOOL -> boolean; WORD/INT/UINT -> integer number. */
export type WireValue = boolean | number;

export interface PointInfo {
  readonly address: string;
  readonly type: PointType;
  readonly dir: PointDir;
  readonly device: string;
  /** Outputs configured `hold`: the safe state keeps their value instead of OFF/0 (absent: false). */
  readonly hold?: boolean;
}

/** Range of a point type's values on the wire. */
export const POINT_RANGE: Record<Exclude<PointType, 'BOOL'>, { min: number; max: number }> = {
  WORD: { min: 0, max: 0xffff },
  UINT: { min: 0, max: 0xffff },
  INT: { min: -0x8000, max: 0x7fff },
};

/** True when `value` is a legal value of `type` (BOOL is a boolean, registers are in-range integers). */
export function valueFits(type: PointType, value: unknown): value is WireValue {
  if (type === 'BOOL') return typeof value === 'boolean';
  if (typeof value !== 'number' || !Number.isInteger(value)) return false;
  const { min, max } = POINT_RANGE[type];
  return value >= min && value <= max;
}

/** The value a point takes in the safe state (OFF / 0). */
export const zeroOf = (type: PointType): WireValue => (type === 'BOOL' ? false : 0);

/**
 * Canonical text of a gateway address (`%ix0.3` -> `%IX0.3`, `%IW02` -> `%IW2`), or undefined when
 * the text is not an input/output bit (`%IXn.b`, `%QXn.b`) or word (`%IWn`, `%QWn`).
 */
export function canonicalAddress(text: string): string | undefined {
  const loc = parseLocation(text);
  if (!loc || loc.area === 'M' || loc.levels) return undefined;
  // I/O bits are 0..7 of a byte (OpenPLC's map and the gateway's): %IX0.12 is no I/O point.
  if (loc.size === 'X' && loc.bit !== undefined) return loc.bit <= 7 ? `%${loc.area}X${loc.index}.${loc.bit}` : undefined;
  if (loc.size === 'W') return `%${loc.area}W${loc.index}`;
  return undefined;
}

/** Direction implied by an address: %I... are inputs, %Q... outputs. */
export const dirOf = (address: string): PointDir => (address.toUpperCase().startsWith('%Q') ? 'out' : 'in');
