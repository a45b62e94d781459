// The gateway's I/O image and safety logic: one controller lease, the watchdog, the safe state.
import type { DeviceStatus, StatusMessage, WatchdogInfo } from '../protocol/messages';
import { valueFits, zeroOf, type PointInfo, type Quality, type WireValue } from '../protocol/points';
import type { Device, Values } from './device';
import type { DevicePoint } from './pointMap';

export interface HubListener {
  inputs(values: Values, quality: ReadonlyMap<string, Quality>): void;
  written(values: Values): void;
  status(): void;
  log(line: string): void;
}

interface Bound {
  readonly info: PointInfo;
  readonly point: DevicePoint;
  readonly device: Device;
}

/** Why a set of values was refused: the protocol error code and plain words. */
export interface Refusal {
  readonly code: 'unknown-address' | 'not-output' | 'not-input' | 'not-simulated' | 'bad-value';
  readonly message: string;
}

/** How long a safe-state write may take before shutdown goes on without it. */
const SAFE_STATE_WAIT_MS = 2000;

export class IoHub {
  readonly points: ReadonlyMap<string, Bound>;
  private controllerSession: string | null = null;
  private armed = true;
  private watchdogState: WatchdogInfo['state'] = 'idle';
  private timer: NodeJS.Timeout | undefined;
  private tripRefusalSent = false;

  constructor(
    readonly devices: readonly Device[],
    private readonly opts: { watchdogMs: number; autoRearm: boolean },
    private readonly listener: HubListener,
  ) {
    const map = new Map<string, Bound>();
    for (const device of devices) {
      for (const point of device.points) {
        map.set(point.address, { info: { address: point.address, type: point.type, dir: point.dir, device: device.info.id }, point, device });
      }
    }
    this.points = map;
  }

  async start(): Promise<void> {
    for (const d of this.devices) {
      await d.start({
        inputs: (v, q) => this.listener.inputs(v, q),
        written: (v) => this.listener.written(v),
        status: () => this.listener.status(),
      });
    }
  }

  pointList(): PointInfo[] {
    return [...this.points.values()].map((b) => b.info);
  }

  /** Full snapshot: inputs as last read, outputs as last written to the device. */
  image(): { values: Record<string, WireValue>; quality: Record<string, Quality> } {
    const values: Record<string, WireValue> = {};
    const quality: Record<string, Quality> = {};
    for (const d of this.devices) {
      const q = d.inputQuality();
      for (const [a, v] of d.inputValues()) {
        values[a] = v;
        quality[a] = q.get(a) ?? 'good';
      }
      for (const p of d.points) {
        if (p.dir !== 'out') continue;
        values[p.address] = d.writtenValues().get(p.address) ?? zeroOf(p.type);
        quality[p.address] = d.state === 'offline' || !d.writtenValues().has(p.address) ? 'stale' : 'good';
      }
    }
    return { values, quality };
  }

  status(): Omit<StatusMessage, 'v' | 't'> {
    const devices: DeviceStatus[] = this.devices.map((d) => ({ id: d.info.id, state: d.state, error: d.error }));
    return {
      devices,
      armed: this.armed,
      watchdog: { ms: this.opts.watchdogMs, state: this.watchdogState, autoRearm: this.opts.autoRearm },
      controller: this.controllerSession !== null,
    };
  }

  /** Grants the controller lease if it is free; returns the role the session gets. */
  claim(session: string, wanted: 'controller' | 'observer'): 'controller' | 'observer' {
    if (wanted === 'controller' && this.controllerSession === null) {
      this.controllerSession = session;
      this.listener.status();
      return 'controller';
    }
    return 'observer';
  }

  isController(session: string): boolean {
    return this.controllerSession === session;
  }

  /** Checks a set of values against the map: every address known, of the wanted direction, value in range. */
  check(values: Record<string, unknown>, dir: 'in' | 'out', simulatedOnly: boolean): Refusal | Map<string, WireValue> {
    const ok = new Map<string, WireValue>();
    for (const [address, value] of Object.entries(values)) {
      const b = this.points.get(address);
      if (!b) return { code: 'unknown-address', message: `${address} is not an I/O point of this gateway` };
      if (b.info.dir !== dir) {
        return dir === 'out'
          ? { code: 'not-output', message: `${address} is an input; only outputs (%Q...) can be written` }
          : { code: 'not-input', message: `${address} is an output; only simulated inputs (%I...) can be set` };
      }
      if (simulatedOnly && b.device.info.kind !== 'simulated') {
        return { code: 'not-simulated', message: `${address} belongs to device "${b.info.device}", not the simulated device` };
      }
      if (!valueFits(b.info.type, value)) {
        const want = b.info.type === 'BOOL' ? 'true or false' : `an integer ${b.info.type === 'INT' ? '-32768..32767' : '0..65535'}`;
        return { code: 'bad-value', message: `${address} is ${b.info.type} and needs ${want}, got ${JSON.stringify(value)}` };
      }
      ok.set(address, value);
    }
    return ok;
  }

  /**
   * The controller's output image of one scan, also its heartbeat. Returns a refusal when the
   * gateway is disarmed after a watchdog trip (once per trip, so a running scan is not flooded).
   */
  outputs(values: ReadonlyMap<string, WireValue>): 'ok' | 'disarmed' | 'silently-disarmed' {
    if (!this.armed) {
      if (!this.opts.autoRearm) {
        if (this.tripRefusalSent) return 'silently-disarmed';
        this.tripRefusalSent = true;
        return 'disarmed';
      }
      this.armed = true;
      this.listener.log('watchdog: re-armed automatically by new outputs');
    }
    const perDevice = new Map<Device, Map<string, WireValue>>();
    for (const [a, v] of values) {
      const b = this.points.get(a);
      if (!b) continue;
      const m = perDevice.get(b.device) ?? new Map<string, WireValue>();
      m.set(a, v);
      perDevice.set(b.device, m);
    }
    for (const d of this.devices) void d.setOutputs(perDevice.get(d) ?? new Map(), true);
    this.feed();
    return 'ok';
  }

  /** Controller STOP: safe state first, then stop writing. The lease stays with the controller. */
  async stop(reason: string): Promise<void> {
    this.clearWatchdog('idle');
    this.listener.log(`safe state: ${reason}`);
    await this.safeState();
    this.listener.status();
  }

  arm(): void {
    this.armed = true;
    this.tripRefusalSent = false;
    if (this.watchdogState === 'tripped') this.watchdogState = 'idle';
    this.listener.status();
  }

  /** The controller's connection closed: safe state, lease free for the next controller. */
  async release(session: string): Promise<void> {
    if (this.controllerSession !== session) return;
    this.controllerSession = null;
    const wasFed = this.watchdogState === 'fed';
    if (wasFed) await this.stop('controller disconnected');
    else this.listener.status();
  }

  /** Shutdown: safe state on every device, then close them. */
  async shutdown(): Promise<void> {
    this.clearWatchdog(this.watchdogState === 'tripped' ? 'tripped' : 'idle');
    await this.safeState();
    await Promise.all(this.devices.map((d) => d.close()));
  }

  /** Every output OFF/0 unless configured `hold`; written once, then writing stops. */
  async safeState(): Promise<void> {
    const writes = this.devices.map((d) => {
      const safe = new Map<string, WireValue>();
      for (const p of d.points) {
        if (p.dir !== 'out') continue;
        safe.set(p.address, p.hold ? (d.writtenValues().get(p.address) ?? zeroOf(p.type)) : zeroOf(p.type));
      }
      return d.setOutputs(safe, false);
    });
    let timer: NodeJS.Timeout | undefined;
    await Promise.race([Promise.allSettled(writes), new Promise((r) => (timer = setTimeout(r, SAFE_STATE_WAIT_MS)))]);
    clearTimeout(timer);
  }

  private feed(): void {
    if (this.timer) this.timer.refresh();
    else this.timer = setTimeout(() => void this.trip(), this.opts.watchdogMs);
    if (this.watchdogState !== 'fed') {
      this.watchdogState = 'fed';
      this.listener.status();
    }
  }

  private clearWatchdog(next: WatchdogInfo['state']): void {
    clearTimeout(this.timer);
    this.timer = undefined;
    this.watchdogState = next;
  }

  private async trip(): Promise<void> {
    this.clearWatchdog('tripped');
    this.armed = false;
    this.tripRefusalSent = false;
    this.listener.log(`watchdog: no outputs for ${this.opts.watchdogMs} ms, safe state written, disarmed until "arm"`);
    this.listener.status();
    await this.safeState();
  }
}
