// The gateway's config file (JSON), validated with zod. Documented in docs/GATEWAY-CONFIG.md.
import { readFileSync } from 'node:fs';
import { isIP } from 'node:net';
import { parse as parseJsonc, parseTree, printParseErrorCode, type Node as JsonNode, type ParseError } from 'jsonc-parser';
import { z } from 'zod';
import { POINT_TYPES } from '../protocol/points';
import { ConfigError, MODBUS_TABLES } from './configTypes';
import { expandPoints, type DevicePoint } from './pointMap';
import { PLANTS, plantById } from '../plant/machines';

const pointEntrySchema = z.strictObject({
  address: z.string().min(1),
  count: z.number().int().min(1).max(2048).default(1),
  table: z.enum(MODBUS_TABLES).optional(),
  register: z.number().int().min(0).max(65535).optional(),
  type: z.enum(POINT_TYPES).optional(),
  hold: z.boolean().default(false),
});

const idSchema = z.string().regex(/^[A-Za-z0-9_.-]{1,40}$/, 'use 1-40 letters, digits, "_", "-" or "."');

/** Why `host` is not a bare host name or IP address (a URL, `host:port`, a path), or undefined when it is one. */
export function hostProblem(host: string): string | undefined {
  if (isIP(host)) return undefined; // IPv4, or IPv6 such as ::1 (colons, no brackets)
  if (/^[0-9.]+$/.test(host)) {
    // All digits and dots reads as an IPv4 address (no top-level domain is numeric): say what is wrong with it.
    const parts = host.split('.');
    const big = parts.find((p) => p !== '' && Number(p) > 255);
    if (big !== undefined) return `${JSON.stringify(host)} is not an IPv4 address: ${big} is above 255 (each of the four numbers is 0-255)`;
    return `${JSON.stringify(host)} is not an IPv4 address: it needs four numbers 0-255 separated by dots (e.g. "192.168.1.10")`;
  }
  if (/^[A-Za-z0-9_](?:[A-Za-z0-9_.-]{0,251}[A-Za-z0-9_])?$/.test(host)) return undefined;
  const text = JSON.stringify(host);
  let url: URL | undefined;
  try {
    url = new URL(/^[A-Za-z][A-Za-z0-9+.-]*:\/\//.test(host) ? host : `tcp://${host}`);
  } catch {
    url = undefined;
  }
  const bare = url?.hostname.replace(/^\[(.*)\]$/, '$1');
  if (url && bare && (isIP(bare) || /^[A-Za-z0-9_.-]+$/.test(bare))) {
    const port = url.port ? ` and the port in "port": ${url.port}` : ' and the port, if not 502, in "port"';
    const what = host.includes('://') ? 'a URL' : url.port ? 'a host with a port' : 'not a bare host';
    return `${text} is ${what}; give the bare host "${bare}"${port}`;
  }
  return `${text} is not a host name or IP address; give the bare host (e.g. "192.168.1.10") and the port in "port"`;
}

const modbusDeviceSchema = z.strictObject({
  id: idSchema,
  type: z.literal('modbus-tcp').default('modbus-tcp'),
  host: z
    .string()
    .min(1)
    .superRefine((host, ctx) => {
      const problem = hostProblem(host);
      if (problem) ctx.addIssue({ code: 'custom', message: problem });
    }),
  port: z.number().int().min(1).max(65535).default(502),
  unitId: z.number().int().min(0).max(255).default(1),
  pollMs: z.number().int().min(10).max(60_000).default(100),
  timeoutMs: z.number().int().min(50).max(60_000).default(1000),
  /**
   * How long a write of the safe image may take to be answered (a slow device): a pending safe write
   * is never abandoned to a reconnect before this; it is then retried on a new connection.
   */
  safeWriteTimeoutMs: z.number().int().min(100).max(120_000).default(10_000),
  /** Read the outputs back before each rewrite, to detect another Modbus master writing them. */
  readBackOutputs: z.boolean().default(true),
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
      /** A machine (docs/PLANTS.md) the device is: its sensors are the inputs, a Modbus master writes its actuators (virtual commissioning). */
      plant: z.string().min(1).optional(),
      /**
       * With a machine: the device's communication watchdog (ms), as an I/O coupler's. No Modbus write to
       * the machine's actuators for this long and the outputs the master wrote fall OFF / 0; 0 turns it off.
       */
      masterWatchdogMs: z
        .number()
        .int()
        .min(0)
        .max(60_000)
        .refine((ms) => ms === 0 || ms >= 100, 'is 0 (off) or 100 to 60000 ms')
        .default(1000),
    })
    .default({ modbusPort: 5020, masterWatchdogMs: 1000 }),
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
  const resolved = { ...cfg, devices };
  checkPlant(resolved, `${source}: simulated.plant`);
  return resolved;
}

/**
 * `--plant` / `simulated.plant`: a machine there is, and the built-in simulated device to be it
 * (it runs only when no `devices` are configured). Throws a ConfigError located at `where`.
 */
export function checkPlant(config: ResolvedConfig, where: string): void {
  const id = config.simulated.plant;
  if (id === undefined) return;
  if (!plantById(id)) throw new ConfigError(where, `there is no machine "${id}"; the machines are ${PLANTS.map((m) => m.id).join(', ')}`);
  if (config.devices.length > 0)
    throw new ConfigError(
      where,
      `the machine "${id}" is the built-in simulated device, which runs only with no "devices" configured; this config names ${config.devices.length} Modbus device(s): drop the devices or the machine`,
    );
}

/** Reads and validates a config file. */
export function loadConfigFile(file: string): ResolvedConfig {
  let text: string;
  try {
    text = readFileSync(file, 'utf8');
  } catch (e) {
    throw new ConfigError(file, `cannot read the config file (${(e as Error).message})`);
  }
  if (text.charCodeAt(0) === 0xfeff) text = text.slice(1); // a UTF-8 byte order mark (Windows editors write one)
  const raw = parseJson(text, file);
  const duplicate = findDuplicateKey(text);
  if (duplicate) {
    throw new ConfigError(
      `${file}: ${duplicate.path}`,
      `key "${duplicate.key}" appears twice in the same object (lines ${duplicate.lines[0]} and ${duplicate.lines[1]}); JSON would silently keep the last one, so remove one`,
    );
  }
  return resolveConfig(raw, file);
}

/** 1-based line and column of a character offset in `text`. */
export function lineColumn(text: string, offset: number): { line: number; column: number } {
  const before = text.slice(0, offset);
  const lineStart = before.lastIndexOf('\n') + 1;
  return { line: before.split('\n').length, column: offset - lineStart + 1 };
}

const PARSE_ERROR_WORDS: Partial<Record<string, string>> = {
  InvalidSymbol: 'unexpected character',
  InvalidNumberFormat: 'invalid number',
  PropertyNameExpected: 'a key in double quotes expected',
  ValueExpected: 'a value expected',
  ColonExpected: '":" expected',
  CommaExpected: '"," expected',
  CloseBraceExpected: '"}" expected',
  CloseBracketExpected: '"]" expected',
  EndOfFileExpected: 'nothing more expected after the end of the JSON value',
  InvalidCommentToken: 'comments are not allowed in JSON',
  UnexpectedEndOfComment: 'comments are not allowed in JSON',
  UnexpectedEndOfString: 'the string is not closed',
  UnexpectedEndOfNumber: 'the number is not complete',
  InvalidUnicode: 'invalid \\u escape',
  InvalidEscapeCharacter: 'invalid escape character',
  InvalidCharacter: 'invalid character in a string (a line break or control character)',
};

/** Strict JSON (no comments, no trailing commas); a syntax error names the line and column. */
function parseJson(text: string, file: string): unknown {
  const errors: ParseError[] = [];
  const value: unknown = parseJsonc(text, errors, { disallowComments: true, allowTrailingComma: false, allowEmptyContent: false });
  const first = errors[0];
  if (first) {
    const { line, column } = lineColumn(text, first.offset);
    const code = printParseErrorCode(first.error);
    const found = text.slice(first.offset, first.offset + Math.min(first.length || 1, 20));
    const near = first.offset >= text.length ? 'at the end of the file' : `at ${JSON.stringify(found)}`;
    throw new ConfigError(`${file}:${line}:${column}`, `not valid JSON: ${PARSE_ERROR_WORDS[code] ?? code} ${near} (line ${line}, column ${column})`);
  }
  return value;
}

export interface DuplicateKey {
  readonly key: string;
  /** JSON path of the duplicated member, e.g. `devices[0].host`. */
  readonly path: string;
  /** 1-based lines of the first and the second occurrence. */
  readonly lines: readonly [number, number];
}

/** A key that appears twice in one object of `text` (valid JSON); an outer object is checked before its members. */
export function findDuplicateKey(text: string): DuplicateKey | undefined {
  const lineOf = (offset: number) => text.slice(0, offset).split('\n').length;
  const walk = (node: JsonNode, path: readonly PropertyKey[]): DuplicateKey | undefined => {
    const items: [PropertyKey, JsonNode | undefined][] = [];
    if (node.type === 'object') {
      const seen = new Map<string, number>();
      for (const prop of node.children ?? []) {
        const [keyNode, value] = prop.children ?? [];
        if (keyNode?.type !== 'string' || typeof keyNode.value !== 'string') continue;
        const key = keyNode.value;
        const first = seen.get(key);
        if (first !== undefined) return { key, path: pathText([...path, key]), lines: [lineOf(first), lineOf(keyNode.offset)] };
        seen.set(key, keyNode.offset);
        items.push([key, value]);
      }
    } else if (node.type === 'array') {
      (node.children ?? []).forEach((item, i) => items.push([i, item]));
    }
    for (const [key, child] of items) {
      const found = child && walk(child, [...path, key]);
      if (found) return found;
    }
    return undefined;
  };
  const root = parseTree(text, [], { disallowComments: true, allowTrailingComma: false });
  return root && walk(root, []);
}
