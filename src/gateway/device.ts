// What the gateway needs from a field device: the simulated one and Modbus TCP couplers alike.
//
// Outputs are a desired state, not a stream of writes: the device keeps one image (the
// controller's while armed, the safe image while disarmed) and writes it whole, from one snapshot,
// on every poll and after every reconnect, so a write that failed is retried and a torn image
// (coils of one scan, registers of another) cannot reach the device.
import type { DeviceInfo, DeviceOutputs, DeviceState } from '../protocol/messages';
import type { Quality, WireValue } from '../protocol/points';
import type { DevicePoint } from './pointMap';

export type Values = ReadonlyMap<string, WireValue>;

export interface DeviceListener {
  /** Input values that changed (or whose quality changed). */
  inputs(values: Values, quality: ReadonlyMap<string, Quality>): void;
  /** Output values now on the device, after a successful write. */
  written(values: Values): void;
  /** Connection state, error text or outputs state changed. */
  status(): void;
  /**
   * The device may have lost its outputs or restarted: its connection dropped, a request timed out,
   * or it went offline. The hub disarms; the device itself already holds the safe image as its
   * desired state from here on, so nothing but the safe image is written until the hub drives it again.
   */
  lost(reason: string): void;
  /**
   * The device's outputs read back differently from what this gateway last wrote and the device
   * acknowledged: another Modbus master (or the device itself) is writing them. The hub disarms; the
   * device writes the safe image once and then stops writing its outputs until it is driven again.
   * `text` names the device and the first difference, in plain words.
   */
  otherMaster?(text: string): void;
  /** A line for the gateway log. */
  log?(line: string): void;
}

export interface Device {
  readonly info: DeviceInfo;
  readonly points: readonly DevicePoint[];
  readonly state: DeviceState;
  readonly error: string | null;
  /** Last input values read and their quality. */
  inputValues(): Values;
  inputQuality(): ReadonlyMap<string, Quality>;
  /** Output values as last written to (acknowledged by) the device. */
  writtenValues(): Values;
  /** `driven`: the controller's image; `safe`: the safe image, acknowledged; `safe-pending`: not yet. */
  outputsState(): DeviceOutputs;
  start(listener: DeviceListener): Promise<void>;
  /**
   * Armed: keep this output image on the device (points not named keep their desired value).
   * Written at once when it changed, and again on every poll so the coupler's own watchdog stays fed.
   * Ignored once the device holds its final safe state (shutdown).
   */
  drive(values: Values): void;
  /**
   * Disarmed: the safe image (every output OFF/0, `hold` points at their last written value) is the
   * desired state from now on, written at once, on every poll and after every reconnect until
   * `drive` is called again. Resolves with whether the device acknowledged it within `waitMs`
   * (it keeps being retried either way).
   */
  safe(waitMs: number): Promise<boolean>;
  /**
   * Shutdown: stop polling, refuse `drive`, let the request on the wire finish, then write the safe
   * image as the last write, retried until `deadlineMs` from now. Resolves with whether the device
   * acknowledged it.
   */
  finalSafe(deadlineMs: number): Promise<boolean>;
  /**
   * While another master was seen writing this device's outputs (and the gateway stopped writing
   * them): what was seen, in plain words; null otherwise.
   */
  conflict?(): string | null;
  /** Why `arm` must wait: another master changed the outputs moments ago; null when arming is allowed. */
  armBlocker?(): string | null;
  /** How long the safe image has been wanted but not acknowledged (ms), or null. */
  safePendingMs?(): number | null;
  /** Requests waiting in the device's queue (a backlog that must not grow). */
  queueDepth(): number;
  close(): Promise<void>;
}

/** The safe image of a device's outputs: OFF/0, or the last written value for `hold` points. */
export function safeImage(points: readonly DevicePoint[], written: Values, zero: (p: DevicePoint) => WireValue): Map<string, WireValue> {
  const image = new Map<string, WireValue>();
  for (const p of points) {
    if (p.dir !== 'out') continue;
    image.set(p.address, p.hold ? (written.get(p.address) ?? zero(p)) : zero(p));
  }
  return image;
}
