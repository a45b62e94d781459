// A Modbus TCP device (I/O coupler or plant simulator) behind a supervisor: one request queue,
// connect and response timeouts, reconnect with backoff 1 s -> 30 s, outputs rewritten every
// poll, `offline` with stale inputs after 3 failed polls.
import type { DeviceState } from '../protocol/messages';
import { zeroOf, type Quality, type WireValue } from '../protocol/points';
import type { ResolvedDevice } from './config';
import type { Device, DeviceListener, Values } from './device';
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
  private readonly desired = new Map<string, WireValue>();
  private rewrite = false;
  private client: ModbusClient | undefined;
  private listener: DeviceListener | undefined;
  private queue: Promise<unknown> = Promise.resolve();
  private depth = 0;
  private writeQueued: Promise<void> | undefined;
  private failedPolls = 0;
  private backoffMs = BACKOFF_FIRST_MS;
  private nextConnectAt = 0;
  private timer: NodeJS.Timeout | undefined;
  private closed = false;
  private writesSincePoll = 0;

  constructor(private readonly cfg: ResolvedDevice) {
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
  queueDepth(): number {
    return Math.max(0, this.depth - 1); // waiting behind the request on the wire
  }

  start(listener: DeviceListener): Promise<void> {
    this.listener = listener;
    void this.tick();
    return Promise.resolve();
  }

  setOutputs(values: Values, rewrite: boolean): Promise<void> {
    let changed = rewrite !== this.rewrite;
    for (const [a, v] of values) {
      if (this.desired.get(a) !== v) changed = true;
      this.desired.set(a, v);
    }
    this.rewrite = rewrite;
    // Unchanged image: the next poll rewrites it anyway.
    if (!this.client?.isOpen || (!changed && rewrite)) return this.writeQueued ?? Promise.resolve();
    // Coalesce: a write still waiting in the queue picks up the newest image when it runs.
    this.writeQueued ??= this.enqueue(async () => {
      this.writeQueued = undefined;
      await this.writeAll();
    }).catch((e: unknown) => this.noteError(e));
    return this.writeQueued;
  }

  async close(): Promise<void> {
    this.closed = true;
    clearTimeout(this.timer);
    await withTimeout(this.queue, this.cfg.timeoutMs, 'pending requests').catch(() => undefined);
    this.dropClient();
  }

  private enqueue<T>(job: () => Promise<T>): Promise<T> {
    this.depth++;
    const run = this.queue.then(job).finally(() => this.depth--);
    this.queue = run.catch(() => undefined);
    return run;
  }

  private async tick(): Promise<void> {
    if (this.closed) return;
    const started = Date.now();
    try {
      if (!this.client?.isOpen) {
        if (started < this.nextConnectAt) throw new Error(this.error ?? 'not connected');
        await this.connect();
      }
      const writtenSincePoll = this.writesSincePoll > 0;
      this.writesSincePoll = 0;
      await this.enqueue(async () => {
        await this.readAll();
        // Rewrite every poll so the coupler's own watchdog stays fed, unless a fresh image just went out.
        if (this.rewrite && !writtenSincePoll) await this.writeAll(true);
      });
      this.pollSucceeded();
    } catch (e) {
      this.pollFailed(e);
    }
    if (this.closed) return;
    this.timer = setTimeout(() => void this.tick(), Math.max(0, this.cfg.pollMs - (Date.now() - started)));
  }

  private async connect(): Promise<void> {
    this.dropClient();
    const client = new ModbusClient();
    client.on('error', () => undefined); // socket errors surface as failed requests
    client.setTimeout(this.cfg.timeoutMs); // before connect: a silent peer must not hang a request
    client.setID(this.cfg.unitId);
    this.client = client;
    try {
      await withTimeout(client.connectTCP(this.cfg.host, { port: this.cfg.port }), this.cfg.timeoutMs, `connect to ${this.info.target}`);
    } catch (e) {
      this.dropClient();
      this.nextConnectAt = Date.now() + this.backoffMs;
      this.backoffMs = Math.min(this.backoffMs * 2, BACKOFF_MAX_MS);
      throw e;
    }
  }

  private dropClient(): void {
    const client = this.client;
    this.client = undefined;
    client?.destroy(() => undefined);
  }

  private async readAll(): Promise<void> {
    const client = this.client;
    if (!client) throw new Error('not connected');
    const changed = new Map<string, WireValue>();
    for (const b of this.readBlocks) {
      const n = b.points.length;
      let raw: readonly (boolean | number)[];
      if (b.table === 'discreteInputs') raw = (await client.readDiscreteInputs(b.start, n)).data;
      else if (b.table === 'coils') raw = (await client.readCoils(b.start, n)).data;
      else if (b.table === 'inputRegisters') raw = (await client.readInputRegisters(b.start, n)).data;
      else raw = (await client.readHoldingRegisters(b.start, n)).data;
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

  private async writeAll(fromPoll = false): Promise<void> {
    const client = this.client;
    if (!client?.isOpen) throw new Error('not connected');
    const changed = new Map<string, WireValue>();
    for (const b of this.writeBlocks) {
      const vals = b.points.map((p) => this.desired.get(p.address) ?? zeroOf(p.type));
      if (b.table === 'coils') await client.writeCoils(b.start, vals.map((v) => v === true));
      else await client.writeRegisters(b.start, vals.map(toRegister));
      b.points.forEach((p, i) => {
        const v = vals[i] ?? zeroOf(p.type);
        if (this.written.get(p.address) !== v) changed.set(p.address, v);
        this.written.set(p.address, v);
      });
    }
    if (!fromPoll) this.writesSincePoll++;
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
    if (this.client && !this.client.isOpen) this.dropClient();
    if (!this.client && this.nextConnectAt < Date.now()) {
      this.nextConnectAt = Date.now() + this.backoffMs; // connection lost: first retry after the backoff
    }
    if (this.client && /timed out/i.test(message(e))) {
      // A silent peer: start over on a fresh connection so late replies cannot be mistaken for new ones.
      this.dropClient();
      this.nextConnectAt = Date.now() + this.backoffMs;
    }
    if (this.failedPolls >= FAILED_POLLS_OFFLINE && this.state !== 'offline') {
      this.state = 'offline';
      for (const a of this.quality.keys()) this.quality.set(a, 'stale');
      this.listener?.inputs(new Map(this.inputs), new Map(this.quality));
      this.listener?.status();
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
