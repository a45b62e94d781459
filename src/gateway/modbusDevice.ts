// A Modbus TCP device (I/O coupler or plant simulator) behind a supervisor: one request queue,
// connect and response timeouts, reconnect with backoff 1 s -> 30 s, `offline` with stale inputs
// after 3 failed polls. The desired output image (driven or safe) is written from one snapshot at
// once when it changes, on every poll and after every reconnect; a lost connection is reported
// (`lost`) so the hub disarms, and from then on only the safe image is written until it is driven again.
import type { DeviceOutputs, DeviceState } from '../protocol/messages';
import { zeroOf, type Quality, type WireValue } from '../protocol/points';
import type { ResolvedDevice } from './config';
import { safeImage, type Device, type DeviceListener, type Values } from './device';
import { ModbusClient } from './modbusLib';
import { fromRegister, planBlocks, toRegister, type RequestBlock } from './modbusPlan';

export const FAILED_POLLS_OFFLINE = 3;
export const BACKOFF_FIRST_MS = 1000;
export const BACKOFF_MAX_MS = 30_000;

const message = (e: unknown) => (e instanceof Error ? e.message : typeof e === 'object' && e && 'message' in e ? String(e.message) : String(e));

function withTimeout<T>(promise: Promise<T>, ms: number, what: string): Promise<T> {
  let timer: NodeJS.Timeout | undefined;
  const timeout = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what} timed out after ${ms} ms`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

export class ModbusTcpDevice implements Device {
  readonly info;
  readonly points;
  state: DeviceState = 'connecting';
  error: string | null = null;
  private readonly readBlocks: RequestBlock[];
  private readonly writeBlocks: RequestBlock[];
  private readonly inputs = new Map<string, WireValue>();
  private readonly quality = new Map<string, Quality>();
  private readonly written = new Map<string, WireValue>();
  /** The output image to keep on the device; starts as the safe image (nothing is driven until armed). */
  private readonly desired = new Map<string, WireValue>();
  private mode: 'drive' | 'safe' = 'safe';
  /** Bumped on every change of `desired`, so a write knows whether it wrote the current image. */
  private desiredVersion = 0;
  /** The safe image is the desired state and the device acknowledged it. */
  private safeAcked = false;
  /** Shutdown: `drive` is refused and polling has stopped. */
  private final = false;
  /** The current desired image has not been written on the current connection yet. */
  private writeDue = true;
  private wroteSincePoll = false;
  /** A connection was open and its loss has not been reported yet. */
  private connected = false;
  private readonly ackWaiters = new Set<() => void>();
  private client: ModbusClient | undefined;
  private listener: DeviceListener | undefined;
  private queue: Promise<unknown> = Promise.resolve();
  private depth = 0;
  private writeQueued = false;
  private failedPolls = 0;
  private backoffMs = BACKOFF_FIRST_MS;
  private nextConnectAt = 0;
  private timer: NodeJS.Timeout | undefined;
  private closed = false;
  private requestTimeoutMs: number;

  constructor(private readonly cfg: ResolvedDevice) {
    this.requestTimeoutMs = cfg.timeoutMs;
    this.info = { id: cfg.id, kind: 'modbus-tcp' as const, target: `${cfg.host}:${cfg.port} unit ${cfg.unitId}` };
    this.points = cfg.resolvedPoints;
    this.readBlocks = planBlocks(this.points.filter((p) => p.dir === 'in'), false);
    this.writeBlocks = planBlocks(this.points.filter((p) => p.dir === 'out'), true);
    for (const p of this.points) {
      if (p.dir === 'in') {
        this.inputs.set(p.address, zeroOf(p.type));
        this.quality.set(p.address, 'stale'); // nothing read yet
      } else this.desired.set(p.address, zeroOf(p.type));
    }
  }

  inputValues(): Values {
    return this.inputs;
  }
  inputQuality(): ReadonlyMap<string, Quality> {
    return this.quality;
  }
  writtenValues(): Values {
    return this.written;
  }
  outputsState(): DeviceOutputs {
    return this.mode === 'drive' ? 'driven' : this.safeAcked ? 'safe' : 'safe-pending';
  }
  queueDepth(): number {
    return Math.max(0, this.depth - 1); // waiting behind the request on the wire
  }

  start(listener: DeviceListener): Promise<void> {
    this.listener = listener;
    void this.tick();
    return Promise.resolve();
  }

  drive(values: Values): void {
    if (this.final || this.closed) return;
    const before = this.outputsState();
    let changed = this.mode !== 'drive';
    this.mode = 'drive';
    this.safeAcked = false;
    for (const [a, v] of values) {
      if (!this.desired.has(a)) continue;
      if (this.desired.get(a) !== v) changed = true;
      this.desired.set(a, v);
    }
    if (before !== this.outputsState()) this.listener?.status();
    if (!changed) return; // unchanged image: the next poll rewrites it anyway
    this.desiredVersion++;
    this.writeDue = true;
    this.scheduleWrite();
  }

  safe(waitMs: number): Promise<boolean> {
    this.enterSafe();
    if (!this.final && !this.closed) this.scheduleWrite();
    return this.waitForAck(waitMs);
  }

  async finalSafe(deadlineMs: number): Promise<boolean> {
    const end = Date.now() + deadlineMs;
    this.final = true;
    clearTimeout(this.timer);
    this.enterSafe();
    // The request on the wire may carry the driven image: let it finish so the safe write is the last.
    await withTimeout(this.queue, Math.max(1, end - Date.now()), 'pending requests').catch(() => undefined);
    while (!this.closed) {
      const left = end - Date.now();
      if (left <= 0) break;
      try {
        if (!this.client?.isOpen) await this.connect(Math.min(this.cfg.timeoutMs, left));
        // Give a slow device all the time that is left to answer the last write.
        this.requestTimeoutMs = Math.max(50, end - Date.now());
        this.client?.setTimeout(this.requestTimeoutMs);
        await this.enqueue(() => this.writeAll(false));
        if (this.safeAcked) return true;
      } catch (e) {
        this.noteError(e);
        if (this.client && (!this.client.isOpen || /timed out/i.test(message(e)))) this.dropClient();
        await new Promise((r) => setTimeout(r, Math.min(100, Math.max(0, end - Date.now()))));
      }
    }
    return this.safeAcked;
  }

  async close(): Promise<void> {
    this.closed = true;
    clearTimeout(this.timer);
    await withTimeout(this.queue, this.cfg.timeoutMs, 'pending requests').catch(() => undefined);
    this.dropClient();
    this.ackWaiters.forEach((w) => w());
  }

  /** The safe image becomes the desired state (once per disarm: hold points keep the value they had then). */
  private enterSafe(): void {
    if (this.mode === 'safe') return;
    this.mode = 'safe';
    this.safeAcked = false;
    const image = safeImage(this.points, this.written, (p) => zeroOf(p.type));
    for (const [a, v] of image) this.desired.set(a, v);
    this.desiredVersion++;
    this.writeDue = true;
    this.listener?.status();
  }

  private waitForAck(waitMs: number): Promise<boolean> {
    if (this.safeAcked) return Promise.resolve(true);
    return new Promise((resolve) => {
      const done = () => {
        clearTimeout(timer);
        this.ackWaiters.delete(done);
        resolve(this.safeAcked);
      };
      const timer = setTimeout(done, waitMs);
      this.ackWaiters.add(done);
    });
  }

  /** Writes the desired image now (coalesced: a write still waiting in the queue takes the newest image when it runs). */
  private scheduleWrite(): void {
    if (!this.client?.isOpen || this.writeQueued) return; // the next poll after (re)connecting writes it
    this.writeQueued = true;
    this.enqueue(async () => {
      this.writeQueued = false;
      await this.writeAll(false);
    }).catch((e: unknown) => this.noteError(e));
  }

  private enqueue<T>(job: () => Promise<T>): Promise<T> {
    this.depth++;
    const run = this.queue.then(job).finally(() => this.depth--);
    this.queue = run.catch(() => undefined);
    return run;
  }

  private async tick(): Promise<void> {
    if (this.closed || this.final) return;
    const started = Date.now();
    try {
      if (!this.client?.isOpen) {
        if (this.client || this.connected) {
          this.dropClient();
          this.connectionLost('the connection closed');
        }
        if (started < this.nextConnectAt) throw new Error(this.error ?? 'not connected');
        await this.connect(this.cfg.timeoutMs);
      }
      await this.enqueue(async () => {
        // Outputs first: the desired image (safe or driven) reaches the device even when its inputs
        // cannot be read. Rewritten every poll so the coupler's own watchdog stays fed, unless a
        // write of the current image went out since the last poll.
        const fresh = this.wroteSincePoll && !this.writeDue;
        this.wroteSincePoll = false;
        if (!fresh) await this.writeAll(true);
        await this.readAll();
      });
      this.pollSucceeded();
    } catch (e) {
      this.pollFailed(e);
    }
    if (this.closed || this.final) return;
    this.timer = setTimeout(() => void this.tick(), Math.max(0, this.cfg.pollMs - (Date.now() - started)));
  }

  private async connect(timeoutMs: number): Promise<void> {
    this.dropClient();
    const client = new ModbusClient();
    client.on('error', () => undefined); // socket errors surface as failed requests
    client.setTimeout(this.requestTimeoutMs); // before connect: a silent peer must not hang a request
    client.setID(this.cfg.unitId);
    this.client = client;
    try {
      await withTimeout(client.connectTCP(this.cfg.host, { port: this.cfg.port }), timeoutMs, `connect to ${this.info.target}`);
    } catch (e) {
      this.dropClient();
      this.nextConnectAt = Date.now() + this.backoffMs;
      this.backoffMs = Math.min(this.backoffMs * 2, BACKOFF_MAX_MS);
      throw e;
    }
    // A new connection may be a restarted device: write the desired image (safe unless driven) first thing.
    this.connected = true;
    this.writeDue = true;
  }

  /**
   * One Modbus request, settled for sure: modbus-serial's own timeout is cancelled without an answer
   * when the connection is destroyed, which would leave the queue (and every later safe write) stuck.
   */
  private request<T>(job: () => Promise<T>): Promise<T> {
    return withTimeout(job(), this.requestTimeoutMs + 100, 'Modbus request');
  }

  private dropClient(): void {
    const client = this.client;
    this.client = undefined;
    client?.destroy(() => undefined);
  }

  /** The device may have restarted or lost its outputs: report it once per connection. */
  private connectionLost(reason: string): void {
    const wasConnected = this.connected;
    this.connected = false;
    this.writeDue = true;
    if (this.safeAcked) {
      this.safeAcked = false; // unknown until written again on the next connection
      this.listener?.status();
    }
    if (wasConnected) this.listener?.lost(reason);
  }

  private async readAll(): Promise<void> {
    const client = this.client;
    if (!client) throw new Error('not connected');
    const changed = new Map<string, WireValue>();
    for (const b of this.readBlocks) {
      const n = b.points.length;
      let raw: readonly (boolean | number)[];
      if (b.table === 'discreteInputs') raw = (await this.request(() => client.readDiscreteInputs(b.start, n))).data;
      else if (b.table === 'coils') raw = (await this.request(() => client.readCoils(b.start, n))).data;
      else if (b.table === 'inputRegisters') raw = (await this.request(() => client.readInputRegisters(b.start, n))).data;
      else raw = (await this.request(() => client.readHoldingRegisters(b.start, n))).data;
      b.points.forEach((p, i) => {
        const r = raw[i];
        const value = typeof r === 'boolean' ? r : fromRegister(p.type, r ?? 0);
        if (this.inputs.get(p.address) !== value || this.quality.get(p.address) !== 'good') changed.set(p.address, value);
        this.inputs.set(p.address, value);
      });
    }
    if (changed.size) {
      for (const a of changed.keys()) this.quality.set(a, 'good');
      this.listener?.inputs(changed, new Map([...changed.keys()].map((a) => [a, 'good' as const])));
    }
  }

  /** Writes one snapshot of the desired image, block by block (coils, then registers). */
  private async writeAll(fromPoll: boolean): Promise<void> {
    const client = this.client;
    if (!client?.isOpen) throw new Error('not connected');
    const version = this.desiredVersion;
    const mode = this.mode;
    const image = this.writeBlocks.map((b) => b.points.map((p) => this.desired.get(p.address) ?? zeroOf(p.type)));
    const changed = new Map<string, WireValue>();
    for (const [i, b] of this.writeBlocks.entries()) {
      const vals = image[i] ?? [];
      if (b.table === 'coils') await this.request(() => client.writeCoils(b.start, vals.map((v) => v === true)));
      else await this.request(() => client.writeRegisters(b.start, vals.map(toRegister)));
      b.points.forEach((p, k) => {
        const v = vals[k] ?? zeroOf(p.type);
        if (this.written.get(p.address) !== v) changed.set(p.address, v);
        this.written.set(p.address, v);
      });
    }
    if (!fromPoll) this.wroteSincePoll = true;
    if (version === this.desiredVersion) {
      this.writeDue = false;
      if (mode === 'safe' && this.mode === 'safe' && !this.safeAcked) {
        this.safeAcked = true;
        this.listener?.status();
        [...this.ackWaiters].forEach((w) => w());
      }
    }
    if (changed.size) this.listener?.written(changed);
  }

  private pollSucceeded(): void {
    this.failedPolls = 0;
    this.backoffMs = BACKOFF_FIRST_MS;
    if (this.state !== 'online' || this.error !== null) {
      this.state = 'online';
      this.error = null;
      this.listener?.status();
    }
  }

  private pollFailed(e: unknown): void {
    this.failedPolls++;
    this.noteError(e);
    const text = message(e);
    if (this.client && !this.client.isOpen) {
      this.dropClient();
      this.connectionLost(text);
    }
    if (!this.client && this.nextConnectAt < Date.now()) {
      this.nextConnectAt = Date.now() + this.backoffMs; // connection lost: first retry after the backoff
    }
    if (this.client && /timed out/i.test(text)) {
      // A silent peer: start over on a fresh connection so late replies cannot be mistaken for new ones.
      this.dropClient();
      this.connectionLost(text);
      this.nextConnectAt = Date.now() + this.backoffMs;
    }
    if (this.failedPolls >= FAILED_POLLS_OFFLINE && this.state !== 'offline') {
      this.state = 'offline';
      for (const a of this.quality.keys()) this.quality.set(a, 'stale');
      this.listener?.inputs(new Map(this.inputs), new Map(this.quality));
      this.listener?.status();
      this.listener?.lost(`offline after ${FAILED_POLLS_OFFLINE} failed polls: ${text}`);
    }
  }

  private noteError(e: unknown): void {
    const text = message(e);
    if (text !== this.error) {
      this.error = text;
      if (this.state === 'offline') this.listener?.status();
    }
  }
}
