// What the gateway needs from a field device: the simulated one and Modbus TCP couplers alike.
import type { DeviceInfo, DeviceState } from '../protocol/messages';
import type { Quality, WireValue } from '../protocol/points';
import type { DevicePoint } from './pointMap';

export type Values = ReadonlyMap<string, WireValue>;

export interface DeviceListener {
  /** Input values that changed (or whose quality changed). */
  inputs(values: Values, quality: ReadonlyMap<string, Quality>): void;
  /** Output values now on the device, after a successful write. */
  written(values: Values): void;
  /** Connection state or error text changed. */
  status(): void;
}

export interface Device {
  readonly info: DeviceInfo;
  readonly points: readonly DevicePoint[];
  readonly state: DeviceState;
  readonly error: string | null;
  /** Last input values read and their quality. */
  inputValues(): Values;
  inputQuality(): ReadonlyMap<string, Quality>;
  /** Output values as last written to the device. */
  writtenValues(): Values;
  start(listener: DeviceListener): Promise<void>;
  /**
   * The output image to keep on the device. `rewrite` true: write now and again on every poll (the
   * device's own watchdog stays fed); false: write this image once (the safe state), then stop writing.
   * Resolves when the write was done or failed.
   */
  setOutputs(values: Values, rewrite: boolean): Promise<void>;
  /** Requests waiting in the device's queue (a backlog that must not grow). */
  queueDepth(): number;
  close(): Promise<void>;
}
