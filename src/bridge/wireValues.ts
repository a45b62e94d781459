// Program values <-> gateway wire values, by the point's type (16-bit registers wrap like a PLC's I/O card).
import type { Value } from '../model/iecTypes';
import type { PointType, WireValue } from '../protocol/points';

const toNumber = (v: Value): number => (typeof v === 'bigint' ? Number(BigInt.asIntN(64, v)) : typeof v === 'boolean' ? (v ? 1 : 0) : typeof v === 'string' ? 0 : v);

/** A program value as the point's wire value: BOOL -> boolean; registers -> the low 16 bits in the point's range. */
export function toWire(type: PointType, value: Value): WireValue {
  if (type === 'BOOL') return typeof value === 'boolean' ? value : toNumber(value) !== 0;
  const u = ((Math.trunc(toNumber(value)) % 0x10000) + 0x10000) % 0x10000;
  return type === 'INT' && u >= 0x8000 ? u - 0x10000 : u;
}

/**
 * A wire value as the value of a program variable of `varType`: 16-bit patterns are reinterpreted
 * (WORD 65535 read into an INT is -1), as a PLC copies the input image into the variable.
 */
export function fromWire(varType: string, value: WireValue): Value {
  if (typeof value === 'boolean') return varType === 'BOOL' ? value : value ? 1 : 0;
  if (varType === 'BOOL') return value !== 0;
  const u = ((value % 0x10000) + 0x10000) % 0x10000;
  return varType === 'INT' && u >= 0x8000 ? u - 0x10000 : u;
}
