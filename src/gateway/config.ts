// The gateway's config file (JSON), validated with zod. Documented in docs/GATEWAY-CONFIG.md.
import { readFileSync } from 'node:fs';
import { z } from 'zod';
import { POINT_TYPES } from '../protocol/points';
import { ConfigError, MODBUS_TABLES } from './configTypes';
import { expandPoints, type DevicePoint } from './pointMap';

const pointEntrySchema = z.strictObject({
  address: z.string().min(1),
  count: z.number().int().min(1).max(2048).default(1),
  table: z.enum(MODBUS_TABLES).optional(),
  register: z.number().int().min(0).max(65535).optional(),
  type: z.enum(POINT_TYPES).optional(),
  hold: z.boolean().default(false),
});

const idSchema = z.string().regex(/^[A-Za-z0-9_.-]{1,40}$/, 'use 1-40 letters, digits, "_", "-" or "."');

const modbusDeviceSchema = z.strictObject({
  id: idSchema,
  type: z.literal('modbus-tcp').default('modbus-tcp'),
  host: z.string().min(1),
  port: z.number().int().min(1).max(65535).default(502),
  unitId: z.number().int().min(0).max(255).default(1),
  pollMs: z.number().int().min(10).max(60_000).default(100),
  timeoutMs: z.number().int().min(50).max(60_000).default(1000),
  points: z.array(pointEntrySchema).min(1),
});

export const configSchema = z.strictObject({
  port: z.number().int().min(0).max(65535).optional(),
  token: z.string().min(16, 'a fixed token needs at least 16 characters').max(256).optional(),
  watchdogMs: z.number().int().min(200).max(5000).default(1000),
  autoRearm: z.boolean().default(false),
  allowedOrigins: z.array(z.string().url()).default([]),
  allowedHosts: z.array(z.string().min(1)).default([]),
  simulated: z
    .strictObject({
      /** Loopback port of the simulated device's Modbus TCP server; 0 picks a free port, null turns it off. */
      modbusPort: z.number().int().min(0).max(65535).nullable().default(5020),
    })
    .default({ modbusPort: 5020 }),
  devices: z.array(modbusDeviceSchema).default([]),
});
export type GatewayConfigFile = z.infer<typeof configSchema>;
export type ModbusDeviceConfig = z.infer<typeof modbusDeviceSchema>;

export interface ResolvedDevice extends ModbusDeviceConfig {
  readonly resolvedPoints: readonly DevicePoint[];
}
export interface ResolvedConfig extends Omit<GatewayConfigFile, 'devices'> {
  readonly devices: readonly ResolvedDevice[];
}

const pathText = (path: readonly PropertyKey[]) =>
  path.reduce<string>((acc, p) => (typeof p === 'number' ? `${acc}[${p}]` : acc ? `${acc}.${String(p)}` : String(p)), '');

/** Validates parsed JSON; throws ConfigError naming the file, the field and the rule broken. */
export function resolveConfig(raw: unknown, source = 'config'): ResolvedConfig {
  const parsed = configSchema.safeParse(raw);
  if (!parsed.success) {
    const lines = parsed.error.issues.map((i) => `  ${pathText(i.path) || '(top level)'}: ${i.message}`);
    throw new ConfigError(source, `invalid gateway config\n${lines.join('\n')}`);
  }
  const cfg = parsed.data;
  const seenIds = new Set<string>();
  const seenAddresses = new Map<string, string>();
  const devices = cfg.devices.map((d, di) => {
    if (seenIds.has(d.id)) throw new ConfigError(`${source}: devices[${di}].id`, `device id "${d.id}" is used twice`);
    seenIds.add(d.id);
    const resolvedPoints = expandPoints(d.points, `${source}: devices[${di}]`);
    for (const p of resolvedPoints) {
      const other = seenAddresses.get(p.address);
      if (other) throw new ConfigError(`${source}: devices[${di}].points`, `${p.address} is already mapped on device "${other}"`);
      seenAddresses.set(p.address, d.id);
    }
    return { ...d, resolvedPoints };
  });
  return { ...cfg, devices };
}

/** Reads and validates a config file. */
export function loadConfigFile(file: string): ResolvedConfig {
  let text: string;
  try {
    text = readFileSync(file, 'utf8');
  } catch (e) {
    throw new ConfigError(file, `cannot read the config file (${(e as Error).message})`);
  }
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch (e) {
    throw new ConfigError(file, `not valid JSON (${(e as Error).message})`);
  }
  return resolveConfig(raw, file);
}
