// From IEC addresses to Modbus tables: the OpenPLC default map, overridable per config entry.
import { canonicalAddress, dirOf, type PointDir, type PointType } from '../protocol/points';
import { parseLocation } from '../model/iecTypes';
import { ConfigError, type ModbusTable, type PointEntry } from './configTypes';

export interface DevicePoint {
  readonly address: string;
  readonly type: PointType;
  readonly dir: PointDir;
  /** Safe state keeps the last value instead of OFF/0. */
  readonly hold: boolean;
  readonly table: ModbusTable;
  readonly register: number;
}

const isBit = (address: string) => /^%[IQ]X/.test(address);

/** OpenPLC: %IXn.b -> discrete input 8n+b, %QXn.b -> coil 8n+b, %IWn -> input register n, %QWn -> holding register n. */
export function openPlcRegister(address: string): { table: ModbusTable; register: number } | undefined {
  const loc = parseLocation(address);
  if (!loc || loc.levels) return undefined; // hierarchical addresses (%IW0.0) have no OpenPLC register
  if (loc.size === 'X' && loc.bit !== undefined && loc.bit <= 7 && loc.index <= 99) {
    return { table: loc.area === 'I' ? 'discreteInputs' : 'coils', register: loc.index * 8 + loc.bit };
  }
  if (loc.size === 'W' && loc.index <= 1023) return { table: loc.area === 'I' ? 'inputRegisters' : 'holdingRegisters', register: loc.index };
  return undefined;
}

/** The address `n` steps after `address` (bits: %IX0.7 -> %IX1.0; words: %IW3 -> %IW4). */
export function nthAddress(address: string, n: number): string {
  const loc = parseLocation(address);
  if (!loc) throw new Error(`not an address: ${address}`);
  if (loc.size === 'X') {
    const bitNo = loc.index * 8 + (loc.bit ?? 0) + n;
    return `%${loc.area}X${Math.floor(bitNo / 8)}.${bitNo % 8}`;
  }
  return `%${loc.area}W${loc.index + n}`;
}

const allowedTables = (dir: PointDir, bit: boolean): readonly ModbusTable[] =>
  bit ? (dir === 'in' ? ['discreteInputs', 'coils'] : ['coils']) : dir === 'in' ? ['inputRegisters', 'holdingRegisters'] : ['holdingRegisters'];

/** Expands config point entries (address + count) into single points; throws ConfigError with the entry's location. */
export function expandPoints(entries: readonly PointEntry[], where: string): DevicePoint[] {
  const out: DevicePoint[] = [];
  const used = new Map<string, string>();
  entries.forEach((e, i) => {
    const at = `${where}.points[${i}]`;
    const first = canonicalAddress(e.address);
    if (!first) throw new ConfigError(at, `"${e.address}" is not an I/O address; use %IXn.b, %QXn.b, %IWn or %QWn`);
    const bit = isBit(first);
    const dir = dirOf(first);
    const type: PointType = e.type ?? (bit ? 'BOOL' : 'WORD');
    if (bit !== (type === 'BOOL')) throw new ConfigError(at, `${first} is a ${bit ? 'bit' : 'word'} address and cannot have type ${type}`);
    const defaults = openPlcRegister(first);
    const table = e.table ?? defaults?.table;
    const start = e.register ?? defaults?.register;
    if (table === undefined || start === undefined) {
      throw new ConfigError(at, `${first} is outside the OpenPLC default map; give "table" and "register"`);
    }
    if (!allowedTables(dir, bit).includes(table)) {
      throw new ConfigError(at, `${first} (${dir === 'in' ? 'input' : 'output'} ${bit ? 'bit' : 'word'}) cannot use Modbus ${table}; use ${allowedTables(dir, bit).join(' or ')}`);
    }
    if (e.hold && dir === 'in') throw new ConfigError(at, `"hold" applies to outputs only, ${first} is an input`);
    for (let k = 0; k < e.count; k++) {
      const address = nthAddress(first, k);
      const register = start + k;
      if ((e.table === undefined || e.register === undefined) && !openPlcRegister(address)) {
        throw new ConfigError(at, `${address} (address ${k + 1} of ${e.count} from ${first}) is outside the OpenPLC default map; give "table" and "register"`);
      }
      if (register > 65535) throw new ConfigError(at, `register ${register} of ${address} is beyond 65535`);
      if (out.some((p) => p.address === address)) throw new ConfigError(at, `${address} is mapped twice`);
      const key = `${table}:${register}`;
      const clash = used.get(key);
      if (clash && dir === 'out') throw new ConfigError(at, `${address} and ${clash} both write ${table} ${register}`);
      used.set(key, address);
      out.push({ address, type, dir, hold: e.hold, table, register });
    }
  });
  return out;
}
