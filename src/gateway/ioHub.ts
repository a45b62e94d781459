// The gateway's I/O image and safety logic: one controller lease, the watchdog, the safe state.
//
// Armed or disarmed is one latch for the whole gateway. It starts disarmed; only the controller's
// `arm` sets it (refused while a device is not online), and everything that can leave a machine in
// an unknown state clears it: STOP, the watchdog, the controller's connection closing, a device
// losing its connection or going offline, shutdown. While disarmed every device keeps the safe image
// as its desired state (written on every poll and reconnect until acknowledged) and `outputs` are
// refused, so nothing re-energises an output without a deliberate arm.
import type { DeviceStatus, DisarmCause, DisarmInfo, StatusMessage, WatchdogInfo } from '../protocol/messages';
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
  readonly code: 'unknown-address' | 'not-output' | 'not-input' | 'not-simulated' | 'bad-value' | 'arm-refused' | 'shutting-down';
  readonly message: string;
}

/** How long STOP waits for the devices to acknowledge the safe state before answering (it is retried after). */
const SAFE_STATE_WAIT_MS = 2000;
/** How long shutdown keeps retrying the last safe write on a device that is slow or unreachable. */
export const SHUTDOWN_SAFE_DEADLINE_MS = 4000;

/** The outcome of shutdown: whether every device acknowledged the safe image as its last write. */
export interface ShutdownReport {
  readonly safe: boolean;
  readonly devices: readonly { readonly id: string; readonly acknowledged: boolean; readonly error: string | null }[];
}

export class IoHub {
  readonly points: ReadonlyMap<string, Bound>;
  private controllerSession: string | null = null;
  private armed = false;
  private disarmInfo: DisarmInfo | null = {
    cause: 'start',
    message: 'the gateway started with every output in the safe state; press Run (or Arm) as controller to drive outputs',
    at: Date.now(),
  };
  private watchdogState: WatchdogInfo['state'] = 'idle';
  private timer: NodeJS.Timeout | undefined;
  private refusalSent = false;
  private closing = false;

  constructor(
    readonly devices: readonly Device[],
    private readonly opts: { watchdogMs: number; autoRearm: boolean; shutdownDeadlineMs?: number },
    private readonly listener: HubListener,
  ) {
    const map = new Map<string, Bound>();
    for (const device of devices) {
      for (const point of device.points) {
        const info: PointInfo = { address: point.address, type: point.type, dir: point.dir, device: device.info.id, ...(point.hold ? { hold: true } : {}) };
        map.set(point.address, { info, point, device });
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
        lost: (reason) => this.deviceLost(d, reason),
        otherMaster: (text) => this.otherMaster(text),
        log: (line) => this.listener.log(line),
      });
      // Nothing is driven before an arm: whatever a previous run left on the outputs is switched off.
      void d.safe(0);
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
    const devices: DeviceStatus[] = this.devices.map((d) => ({
      id: d.info.id,
      state: d.state,
      error: d.error,
      outputs: d.outputsState(),
      safePendingMs: d.safePendingMs?.() ?? null,
      conflict: d.conflict?.() ?? null,
    }));
    return {
      devices,
      armed: this.armed,
      disarm: this.armed ? null : this.disarmInfo,
      watchdog: { ms: this.opts.watchdogMs, state: this.watchdogState, autoRearm: this.opts.autoRearm },
      controller: this.controllerSession !== null,
    };
  }

  get isArmed(): boolean {
    return this.armed;
  }

  /** Why outputs are refused right now, in plain words. */
  disarmReason(): string {
    return this.disarmInfo?.message ?? 'outputs are disarmed';
  }

  /** Grants the controller lease if it is free; returns the role the session gets. */
  claim(session: string, wanted: 'controller' | 'observer'): 'controller' | 'observer' {
    if (wanted === 'controller' && this.controllerSession === null && !this.closing) {
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
   * The controller's output image of one scan, also its heartbeat. Refused while disarmed (the
   * refusal is reported once per disarm, so a running scan is not flooded) and during shutdown.
   */
  outputs(values: ReadonlyMap<string, WireValue>): 'ok' | 'disarmed' | 'silently-disarmed' | 'shutting-down' {
    if (this.closing) return 'shutting-down';
    if (!this.armed) {
      const rearm = this.opts.autoRearm && this.disarmInfo?.cause === 'watchdog' && this.devicesDown().length === 0;
      if (!rearm) {
        if (this.refusalSent) return 'silently-disarmed';
        this.refusalSent = true;
        return 'disarmed';
      }
      this.setArmed();
      this.listener.log('watchdog: re-armed automatically by new outputs (autoRearm)');
    }
    const perDevice = new Map<Device, Map<string, WireValue>>();
    for (const [a, v] of values) {
      const b = this.points.get(a);
      if (!b) continue;
      const m = perDevice.get(b.device) ?? new Map<string, WireValue>();
      m.set(a, v);
      perDevice.set(b.device, m);
    }
    for (const d of this.devices) d.drive(perDevice.get(d) ?? new Map());
    this.feed();
    return 'ok';
  }

  /** Controller STOP (or the Safe state button): safe state, latched until `arm`. The lease stays with the controller. */
  async stop(reason: string): Promise<void> {
    this.disarm('stop', `STOP (${reason}): outputs are held in the safe state until the controller arms again (Run or Arm)`);
    await this.waitSafe(SAFE_STATE_WAIT_MS);
  }

  /** The controller's deliberate re-arm; refused while a device is not online (it could be restarting). */
  arm(): Refusal | null {
    if (this.closing) return { code: 'shutting-down', message: 'the gateway is shutting down' };
    const down = this.devicesDown();
    if (down.length > 0) {
      const d = down[0]!;
      return {
        code: 'arm-refused',
        message: `device "${d.info.id}" is ${d.state}${d.error ? ` (${d.error})` : ''}: outputs stay in the safe state; arm again when it is online`,
      };
    }
    for (const d of this.devices) {
      const blocker = d.armBlocker?.();
      if (blocker) return { code: 'arm-refused', message: `${blocker}; outputs stay in the safe state` };
    }
    if (!this.armed) {
      this.setArmed();
      this.listener.log('outputs armed by the controller');
    }
    return null;
  }

  /** The controller's connection closed: safe state, lease free for the next controller. */
  async release(session: string): Promise<void> {
    if (this.controllerSession !== session) return;
    this.controllerSession = null;
    this.disarm('controller-lost', 'the controller disconnected: outputs are held in the safe state until a controller arms again');
    await this.waitSafe(SAFE_STATE_WAIT_MS);
  }

  /**
   * Shutdown: refuse everything from now on, then write the safe image as the last write on every
   * device (retried until the deadline), then close them. Reports whether every device acknowledged.
   */
  async shutdown(): Promise<ShutdownReport> {
    if (!this.closing) {
      this.closing = true;
      this.disarm('shutdown', 'the gateway is shutting down: outputs are in the safe state');
    }
    const deadline = this.opts.shutdownDeadlineMs ?? SHUTDOWN_SAFE_DEADLINE_MS;
    const acked = await Promise.all(this.devices.map((d) => d.finalSafe(deadline).catch(() => false)));
    await Promise.all(this.devices.map((d) => d.close()));
    const devices = this.devices.map((d, i) => ({ id: d.info.id, acknowledged: acked[i] === true, error: d.error }));
    return { safe: devices.every((d) => d.acknowledged), devices };
  }

  private setArmed(): void {
    this.armed = true;
    this.disarmInfo = null;
    this.refusalSent = false;
    if (this.watchdogState === 'tripped') this.watchdogState = 'idle';
    this.listener.status();
  }

  /**
   * Clears the latch and makes the safe image every device's desired state. The first cause is kept
   * while already disarmed (it is why the outputs are off).
   */
  private disarm(cause: DisarmCause, message: string): void {
    const wasArmed = this.armed;
    clearTimeout(this.timer);
    this.timer = undefined;
    if (cause === 'watchdog') this.watchdogState = 'tripped';
    else if (this.watchdogState === 'fed') this.watchdogState = 'idle';
    this.armed = false;
    // Another master is news even while disarmed: it is why this gateway stopped writing a device.
    if (wasArmed || cause === 'shutdown' || cause === 'other-master') {
      this.disarmInfo = { cause, message, at: Date.now() };
      this.refusalSent = false;
      this.listener.log(`disarmed (${cause}): ${message}`);
    }
    for (const d of this.devices) void d.safe(0);
    this.listener.status();
  }

  private deviceLost(d: Device, reason: string): void {
    if (this.closing) return;
    if (this.armed) {
      this.disarm('device-lost', `device "${d.info.id}" lost its connection (${reason}); it may have restarted, so its outputs are not written again until the controller arms`);
    } else this.listener.status();
  }

  /** Another Modbus master writes a device's outputs: disarm and say so; the device stops writing them. */
  private otherMaster(text: string): void {
    if (this.closing) return;
    this.disarm(
      'other-master',
      `${text}: disarmed. This gateway switched off the outputs it still drove there and stops writing that device's outputs, so the two masters do not fight; stop the other master, then arm`,
    );
  }

  private devicesDown(): Device[] {
    return this.devices.filter((d) => d.state !== 'online');
  }

  private async waitSafe(ms: number): Promise<void> {
    await Promise.allSettled(this.devices.map((d) => d.safe(ms)));
  }

  private feed(): void {
    if (this.timer) this.timer.refresh();
    else this.timer = setTimeout(() => this.trip(), this.opts.watchdogMs);
    if (this.watchdogState !== 'fed') {
      this.watchdogState = 'fed';
      this.listener.status();
    }
  }

  private trip(): void {
    this.timer = undefined;
    this.disarm('watchdog', `watchdog: no outputs from the controller for ${this.opts.watchdogMs} ms (tab paused, starved or crashed): outputs are held in the safe state until the controller arms`);
  }
}
