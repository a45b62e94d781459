// Protocol v1 between the browser and the gateway (GATEWAY.md): JSON text frames, every
// message `{"v":1,"t":"<type>", ...}`, validated with zod on both sides.
import { z } from 'zod';
import { POINT_TYPES } from './points';

export const PROTOCOL_VERSION = 1;
/** Frames above this size are refused with an `error` reply (GATEWAY.md security defaults). */
export const MAX_FRAME_BYTES = 64 * 1024;
/** Most values one message may carry (far above any real I/O image, far below a memory attack). */
export const MAX_VALUES = 4096;
/** WebSocket path of the gateway endpoint. */
export const IO_PATH = '/io';

const v = z.literal(PROTOCOL_VERSION);
const seq = z.number().int().nonnegative().max(Number.MAX_SAFE_INTEGER);
const wireValue = z.union([z.boolean(), z.number().finite()]);
const values = z
  .record(z.string().max(32), wireValue)
  .refine((o) => Object.keys(o).length <= MAX_VALUES, { message: `at most ${MAX_VALUES} values per message` });
const quality = z.record(z.string().max(32), z.enum(['good', 'stale']));
export const roleSchema = z.enum(['controller', 'observer']);
export type Role = z.infer<typeof roleSchema>;

// ---- client -> gateway -------------------------------------------------------------------
export const helloSchema = z.strictObject({ v, t: z.literal('hello'), token: z.string().min(1).max(256), role: roleSchema });
export const outputsSchema = z.strictObject({ v, t: z.literal('outputs'), seq, values });
export const stopSchema = z.strictObject({ v, t: z.literal('stop'), seq: seq.optional() });
export const armSchema = z.strictObject({ v, t: z.literal('arm'), seq: seq.optional() });
export const resyncSchema = z.strictObject({ v, t: z.literal('resync'), seq: seq.optional() });
/**
 * Extension of v1 for the built-in simulated device only: set its inputs (%IX/%IW) as a plant
 * would. Any authenticated session may send it; addresses on real devices are refused.
 */
export const simulateSchema = z.strictObject({ v, t: z.literal('simulate'), seq: seq.optional(), values });

export const clientMessageSchema = z.discriminatedUnion('t', [
  helloSchema,
  outputsSchema,
  stopSchema,
  armSchema,
  resyncSchema,
  simulateSchema,
]);
export type ClientMessage = z.infer<typeof clientMessageSchema>;
export type ClientMessageType = ClientMessage['t'];
export const CLIENT_MESSAGE_TYPES: readonly ClientMessageType[] = ['hello', 'outputs', 'stop', 'arm', 'resync', 'simulate'];

// ---- gateway -> client -------------------------------------------------------------------
export const pointSchema = z.object({
  address: z.string(),
  type: z.enum(POINT_TYPES),
  dir: z.enum(['in', 'out']),
  device: z.string(),
  /** An output configured `hold`: its safe value is its last value, not OFF/0. */
  hold: z.boolean().optional(),
});
export const deviceStateSchema = z.enum(['connecting', 'online', 'offline']);
export type DeviceState = z.infer<typeof deviceStateSchema>;
export const deviceInfoSchema = z.object({
  id: z.string(),
  kind: z.enum(['simulated', 'modbus-tcp']),
  /** Human description: `simulated`, or `127.0.0.1:502 unit 1`. */
  target: z.string(),
});
export type DeviceInfo = z.infer<typeof deviceInfoSchema>;
/**
 * What the gateway keeps on a device's outputs: `driven` the controller's image (armed); `safe` the
 * safe image, acknowledged by the device; `safe-pending` the safe image is wanted but the device has
 * not acknowledged it yet (unreachable, slow or refusing): it is retried on every poll and reconnect.
 */
export const deviceOutputsSchema = z.enum(['driven', 'safe', 'safe-pending']);
export type DeviceOutputs = z.infer<typeof deviceOutputsSchema>;
export const deviceStatusSchema = z.object({
  id: z.string(),
  state: deviceStateSchema,
  error: z.string().nullable(),
  outputs: deviceOutputsSchema,
  /**
   * Extension of v1 (optional, older gateways omit it): how long (ms) the safe image has been wanted
   * and not acknowledged (a slow or unreachable device), null when not pending.
   */
  safePendingMs: z.number().nonnegative().nullable().optional(),
  /**
   * Extension of v1 (optional): another Modbus master was seen writing this device's outputs and the
   * gateway stopped writing them until armed again, in plain words; null otherwise.
   */
  conflict: z.string().nullable().optional(),
});
export type DeviceStatus = z.infer<typeof deviceStatusSchema>;
/** `idle`: no lease running (no outputs yet, or stopped); `fed`: outputs arriving; `tripped`: lease expired. */
export const watchdogSchema = z.object({ ms: z.number().int(), state: z.enum(['idle', 'fed', 'tripped']), autoRearm: z.boolean() });
export type WatchdogInfo = z.infer<typeof watchdogSchema>;

export const welcomeSchema = z.object({
  v,
  t: z.literal('welcome'),
  session: z.string(),
  role: roleSchema,
  points: z.array(pointSchema),
  devices: z.array(deviceInfoSchema),
  /** The fastest device poll in ms: outputs sent more often than this are never written (a controller coalesces them). */
  pollMs: z.number().int().positive().optional(),
});
export const imageSchema = z.object({ v, t: z.literal('image'), seq, values, quality });
export const inputsSchema = z.object({ v, t: z.literal('inputs'), seq, values, quality });
/** Extension of v1: output values as last written to the device, when they change (observers see outputs live). */
export const writtenSchema = z.object({ v, t: z.literal('written'), seq, values });
/**
 * Why the outputs are disarmed (held in the safe state until a controller sends `arm`):
 * `start` no controller has armed since the gateway started; `stop` the controller sent stop (STOP
 * or the Safe state button); `watchdog` the lease expired; `controller-lost` the controller's
 * connection closed; `device-lost` a device's connection was lost or it went offline (it may have
 * restarted: its outputs are never re-written without an arm); `shutdown` the gateway is exiting;
 * `other-master` (added in v1, for gateways that detect it) another Modbus master was seen writing a
 * device's outputs.
 */
export const DISARM_CAUSES = ['start', 'stop', 'watchdog', 'controller-lost', 'device-lost', 'shutdown', 'other-master'] as const;
export type DisarmCause = (typeof DISARM_CAUSES)[number];
export const disarmSchema = z.object({
  cause: z.enum(DISARM_CAUSES),
  /** Plain words for the Hardware panel: what happened and what to do. */
  message: z.string(),
  /** Wall-clock time of the disarm (ms since 1970). */
  at: z.number(),
});
export type DisarmInfo = z.infer<typeof disarmSchema>;
export const statusSchema = z.object({
  v,
  t: z.literal('status'),
  devices: z.array(deviceStatusSchema),
  armed: z.boolean(),
  /** Why the outputs are disarmed; null while armed. */
  disarm: disarmSchema.nullable(),
  watchdog: watchdogSchema,
  /** Whether some session holds the controller lease. */
  controller: z.boolean(),
});
export const ERROR_CODES = [
  'bad-json',
  'bad-message',
  'too-large',
  'not-hello',
  'bad-token',
  'already-hello',
  'not-controller',
  'unknown-address',
  'not-output',
  'not-input',
  'not-simulated',
  'bad-value',
  'disarmed',
  'arm-refused',
  'flood',
  'shutting-down',
  /** A request answered at most so often (resync) came too soon; nothing is closed. */
  'too-often',
] as const;
export type ErrorCode = (typeof ERROR_CODES)[number];
export const errorSchema = z.object({
  v,
  t: z.literal('error'),
  code: z.enum(ERROR_CODES),
  message: z.string(),
  /** The offending message's seq, or its type when it had no seq, or null when it could not be read. */
  ref: z.union([z.number(), z.string(), z.null()]),
});

export const gatewayMessageSchema = z.discriminatedUnion('t', [
  welcomeSchema,
  imageSchema,
  inputsSchema,
  writtenSchema,
  statusSchema,
  errorSchema,
]);
export type GatewayMessage = z.infer<typeof gatewayMessageSchema>;
export type Welcome = z.infer<typeof welcomeSchema>;
export type ImageMessage = z.infer<typeof imageSchema>;
export type InputsMessage = z.infer<typeof inputsSchema>;
export type WrittenMessage = z.infer<typeof writtenSchema>;
export type StatusMessage = z.infer<typeof statusSchema>;
export type ErrorMessage = z.infer<typeof errorSchema>;

/** Distributive Omit so each union member keeps its own fields. */
type WithoutV<T> = T extends unknown ? Omit<T, 'v'> : never;
export type GatewayMessageBody = WithoutV<GatewayMessage>;
export type ClientMessageBody = WithoutV<ClientMessage>;

/** Short readable description of a zod failure: `values.%QX0.0: expected boolean`. */
export function describeIssues(error: z.ZodError): string {
  return error.issues
    .slice(0, 3)
    .map((i) => `${i.path.length ? i.path.join('.') + ': ' : ''}${i.message}`)
    .join('; ');
}
