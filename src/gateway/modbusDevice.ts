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
/** How often a request in flight checks that its connection is still open (see `request`). */
const CONNECTION_CHECK_MS = 25;
export const BACKOFF_MAX_MS = 30_000;
/** After another master last changed a device's outputs, `arm` waits this long (it is probably still running). */
export const OTHER_MASTER_QUIET_MS = 3000;

const onOff = (v: WireValue) => (typeof v === 'boolean' ? (v ? 'ON' : 'OFF') : String(v));
const isTimeout = (e: unknown) => /timed out/i.test(message(e));
/** A Modbus exception response (the device answered, refusing the request). */
const isModbusException = (e: unknown) => typeof e === 'object' && e !== null && 'modbusCode' in e;

const message = (e: unknown) =>
  e instanceof Error
    ? e.message
    : typeof e === 'object' && e && 'message' in e
      ? String(e.message)
      : String(e);

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
  /** The `hold` outputs, read back before the safe image is written on a new connection. */
  private readonly holdBlocks: RequestBlock[];
  /**
   * A new connection (or the first): what the device's `hold` outputs hold is unknown (a coupler that
   * restarted dropped them). The safe image keeps them as the device holds them, read back before it
   * is written: a held output the restart switched off is not switched on again while disarmed.
   */
  private holdsUnknown = true;
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
  /** Since when the safe image is wanted and not acknowledged (null: acknowledged, or driven). */
  private safeSince: number | null = Date.now();
  private pendingTimer: NodeJS.Timeout | undefined;
  private pendingLogged = false;
  /** The last safe write timed out after its own (long) deadline: start over on a new connection. */
  private safeWriteTimedOut = false;
  // Read-back of the outputs (another master): what the outputs should read now (our last
  // acknowledged write, or what was read back last), valid once written on this connection.
  private readBackOn: boolean;
  private readBackRefused: string | null = null;
  private baselineValid = false;
  private readonly lastSeen = new Map<string, WireValue>();
  /** Another master was seen: the safe image is written once, then nothing until driven again. */
  private handsOff = false;
  private conflictText: string | null = null;
  private foreignChangeAt = 0;
  private readonly aborters = new Set<() => void>();

  constructor(private readonly cfg: ResolvedDevice) {
    this.requestTimeoutMs = cfg.timeoutMs;
    this.readBackOn = cfg.readBackOutputs;
    this.info = {
      id: cfg.id,
      kind: 'modbus-tcp' as const,
      target: `${cfg.host}:${cfg.port} unit ${cfg.unitId}`,
    };
    this.points = cfg.resolvedPoints;
    this.readBlocks = planBlocks(
      this.points.filter((p) => p.dir === 'in'),
      false,
    );
    this.writeBlocks = planBlocks(
      this.points.filter((p) => p.dir === 'out'),
      true,
    );
    this.holdBlocks = planBlocks(
      this.points.filter((p) => p.dir === 'out' && p.hold),
      false,
    );
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
  conflict(): string | null {
    return this.handsOff ? this.conflictText : null;
  }
  armBlocker(): string | null {
    const ago = Date.now() - this.foreignChangeAt;
    if (!this.handsOff || ago >= OTHER_MASTER_QUIET_MS) return null;
    return `${this.conflictText ?? `another Modbus master is writing device "${this.info.id}"'s outputs`}; they changed ${(ago / 1000).toFixed(1)} s ago: stop the other master, then arm`;
  }
  safePendingMs(): number | null {
    return this.mode === 'safe' && !this.safeAcked && this.safeSince !== null
      ? Date.now() - this.safeSince
      : null;
  }
  queueDepth(): number {
    return Math.max(0, this.depth - 1); // waiting behind the request on the wire
  }

  start(listener: DeviceListener): Promise<void> {
    this.listener = listener;
    this.setSafeAcked(false); // the safe image is pending from the start
    void this.tick();
    return Promise.resolve();
  }

  drive(values: Values): void {
    if (this.final || this.closed) return;
    const before = this.outputsState();
    let changed = this.mode !== 'drive';
    this.mode = 'drive';
    this.setSafeAcked(false);
    if (this.handsOff) {
      // Armed again by the operator: writing resumes; what the other master left is not a conflict of ours.
      this.handsOff = false;
      this.conflictText = null;
      this.baselineValid = false;
      changed = true;
    }
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
    // Not for the whole deadline: a request the device lost (it restarted under it) never finishes, and
    // the safe write needs time left to go out again on a fresh connection.
    const drained = await withTimeout(
      this.queue,
      Math.max(1, Math.floor(deadlineMs / 2)),
      'pending requests',
    ).then(
      () => true,
      () => false,
    );
    // Only a safe write waits that long (every other request gives up after timeoutMs), so dropping its
    // connection can never let a driven image land after the safe one.
    if (!drained) this.dropClient();
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
    clearInterval(this.pendingTimer);
    await withTimeout(this.queue, this.cfg.timeoutMs, 'pending requests').catch(() => undefined);
    this.dropClient();
    this.ackWaiters.forEach((w) => w());
  }

  /** The safe image becomes the desired state (once per disarm: hold points keep the value they had then). */
  private enterSafe(): void {
    if (this.mode === 'safe') return;
    this.mode = 'safe';
    this.setSafeAcked(false);
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
      // A poll that ran meanwhile may have written the current image already: a second write of it
      // would only overwrite what another master wrote in between (a flip of ours, unseen).
      if (!this.writeDue) return;
      // Read back first, as every poll does: never write over another master's change unseen.
      if (this.readBackDue()) await this.readBack();
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
        // Read the outputs back first: another master writing them shows as a difference from our
        // last acknowledged write (nothing of ours is in flight: this queue is the only writer).
        this.readBackRefused = null;
        if (this.readBackDue()) await this.readBack();
        const wrote = !fresh && (await this.writeAll(true));
        if (this.readBackRefused !== null && wrote) {
          // The device takes writes but refuses reads of the same outputs: detection is not possible.
          this.readBackOn = false;
          this.listener?.log?.(
            `device "${this.info.id}" refuses reads of its outputs (${this.readBackRefused}): another Modbus master writing them cannot be detected`,
          );
        }
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
    client.on('close', () => {
      if (this.client === client) [...this.aborters].forEach((abort) => abort());
    });
    client.setTimeout(this.requestTimeoutMs); // before connect: a silent peer must not hang a request
    client.setID(this.cfg.unitId);
    this.client = client;
    try {
      await withTimeout(
        client.connectTCP(this.cfg.host, { port: this.cfg.port }),
        timeoutMs,
        `connect to ${this.info.target}`,
      );
    } catch (e) {
      this.dropClient();
      this.nextConnectAt = Date.now() + this.backoffMs;
      this.backoffMs = Math.min(this.backoffMs * 2, BACKOFF_MAX_MS);
      throw e;
    }
    // A new connection may be a restarted device: write the desired image (safe unless driven) first thing.
    this.connected = true;
    this.writeDue = true;
    this.holdsUnknown = true;
    // A new connection may be a restarted device: nothing of ours to compare with until written again.
    // Hands off (another master seen), nothing is written: keep comparing with what was read back last.
    this.baselineValid = this.handsOff;
  }

  /**
   * One Modbus request, settled for sure: modbus-serial's own timeout is cancelled without an answer
   * when the connection is destroyed, which would leave the queue (and every later safe write) stuck.
   */
  private request<T>(job: () => Promise<T>, timeoutMs = this.requestTimeoutMs): Promise<T> {
    const client = this.client;
    if (!client?.isOpen) return Promise.reject(new Error('not connected'));
    client.setTimeout(timeoutMs);
    // A connection that closes settles the request at once (a long safe write must not wait out its deadline).
    let abort: () => void = () => undefined;
    const closed = new Promise<never>((_, reject) => {
      abort = () => reject(new Error('the connection closed'));
    });
    this.aborters.add(abort);
    // modbus-serial marks its port closed on a socket error (a reset connection, ECONNRESET) and then
    // does not relay the 'close' event: without this check a request on a reset connection waited
    // out its whole timeout (10 s for a safe write, past the shutdown's deadline).
    const watch = setInterval(() => {
      if (!client.isOpen) abort();
    }, CONNECTION_CHECK_MS);
    // A long wait (the safe write on a slow device) still counts as failed polls every timeoutMs, so
    // the device goes offline with stale inputs as promptly as a device that does not answer at all.
    const slow =
      timeoutMs > this.requestTimeoutMs
        ? setInterval(() => this.noteSlow(timeoutMs), Math.max(this.requestTimeoutMs, this.cfg.pollMs))
        : undefined;
    return withTimeout(Promise.race([job(), closed]), timeoutMs + 100, 'Modbus request').finally(() => {
      clearInterval(slow);
      clearInterval(watch);
      this.aborters.delete(abort);
    });
  }

  /** The safe write has waited another `timeoutMs` without an answer: one more failed poll, the connection kept. */
  private noteSlow(waitMs: number): void {
    this.failedPolls++;
    this.noteError(
      new Error(
        `request timed out after ${this.cfg.timeoutMs} ms; the safe write keeps waiting up to ${waitMs} ms for the answer`,
      ),
    );
    this.offlineIfDue(this.error ?? 'no answer');
  }

  private dropClient(): void {
    const client = this.client;
    this.client = undefined;
    client?.destroy(() => undefined);
    [...this.aborters].forEach((abort) => abort());
  }

  /** The device may have restarted or lost its outputs: report it once per connection. */
  private connectionLost(reason: string): void {
    const wasConnected = this.connected;
    this.connected = false;
    this.writeDue = true;
    if (this.safeAcked && !this.handsOff) {
      this.setSafeAcked(false); // unknown until written again on the next connection
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
      if (b.table === 'discreteInputs')
        raw = (await this.request(() => client.readDiscreteInputs(b.start, n))).data;
      else if (b.table === 'coils') raw = (await this.request(() => client.readCoils(b.start, n))).data;
      else if (b.table === 'inputRegisters')
        raw = (await this.request(() => client.readInputRegisters(b.start, n))).data;
      else raw = (await this.request(() => client.readHoldingRegisters(b.start, n))).data;
      b.points.forEach((p, i) => {
        const r = raw[i];
        const value = typeof r === 'boolean' ? r : fromRegister(p.type, r ?? 0);
        if (this.inputs.get(p.address) !== value || this.quality.get(p.address) !== 'good')
          changed.set(p.address, value);
        this.inputs.set(p.address, value);
      });
    }
    if (changed.size) {
      for (const a of changed.keys()) this.quality.set(a, 'good');
      this.listener?.inputs(changed, new Map([...changed.keys()].map((a) => [a, 'good' as const])));
    }
  }

  /**
   * Writes one snapshot of the desired image, block by block (coils, then registers); false when
   * nothing was written (hands off after another master was seen, the safe image already written).
   * A write of the safe image waits as long as a slow device needs (`safeWriteTimeoutMs`).
   */
  private async writeAll(fromPoll: boolean): Promise<boolean> {
    const client = this.client;
    if (!client?.isOpen) throw new Error('not connected');
    if (!this.final && this.handsOff && this.mode === 'safe' && this.safeAcked) return false;
    if (this.mode === 'safe' && this.holdsUnknown) await this.keepHolds();
    const version = this.desiredVersion;
    const mode = this.mode;
    const timeoutMs =
      mode === 'safe' && !this.final
        ? Math.max(this.requestTimeoutMs, this.cfg.safeWriteTimeoutMs)
        : this.requestTimeoutMs;
    const image = this.writeBlocks.map((b) =>
      b.points.map((p) => this.desired.get(p.address) ?? zeroOf(p.type)),
    );
    const changed = new Map<string, WireValue>();
    try {
      for (const [i, b] of this.writeBlocks.entries()) {
        const vals = image[i] ?? [];
        if (b.table === 'coils')
          await this.request(
            () =>
              client.writeCoils(
                b.start,
                vals.map((v) => v === true),
              ),
            timeoutMs,
          );
        else await this.request(() => client.writeRegisters(b.start, vals.map(toRegister)), timeoutMs);
        b.points.forEach((p, k) => {
          const v = vals[k] ?? zeroOf(p.type);
          if (this.written.get(p.address) !== v) changed.set(p.address, v);
          this.written.set(p.address, v);
          this.lastSeen.set(p.address, v);
        });
      }
    } catch (e) {
      this.baselineValid = false; // what the device holds now is unknown until the next acknowledged write
      if (mode === 'safe' && isTimeout(e)) this.safeWriteTimedOut = true;
      if (changed.size) this.listener?.written(changed);
      throw e;
    }
    this.baselineValid = true;
    this.holdsUnknown = false;
    if (!fromPoll) this.wroteSincePoll = true;
    if (version === this.desiredVersion) {
      this.writeDue = false;
      if (mode === 'safe' && this.mode === 'safe' && !this.safeAcked) {
        this.setSafeAcked(true);
        this.listener?.status();
        [...this.ackWaiters].forEach((w) => w());
      }
    }
    if (changed.size) this.listener?.written(changed);
    return true;
  }

  /**
   * The safe image on a new connection: each `hold` output keeps what the device holds now (read
   * back), not the value last written on an earlier connection, which a restarted coupler no longer
   * has. A device that refuses the read gets OFF/0 there (the safe direction), and the log says so.
   */
  private async keepHolds(): Promise<void> {
    const client = this.client;
    if (!client) throw new Error('not connected');
    const seen = new Map<string, WireValue>();
    // Part of the safe write: it waits for a slow device as long as the write itself does.
    const timeoutMs = this.final
      ? this.requestTimeoutMs
      : Math.max(this.requestTimeoutMs, this.cfg.safeWriteTimeoutMs);
    try {
      for (const b of this.holdBlocks) {
        const n = b.points.length;
        const raw =
          b.table === 'coils'
            ? (await this.request(() => client.readCoils(b.start, n), timeoutMs)).data
            : (await this.request(() => client.readHoldingRegisters(b.start, n), timeoutMs)).data;
        b.points.forEach((p, i) => {
          const r = raw[i];
          seen.set(p.address, typeof r === 'boolean' ? r : fromRegister(p.type, r ?? 0));
        });
      }
    } catch (e) {
      if (isTimeout(e)) this.safeWriteTimedOut = true;
      if (!isModbusException(e)) throw e;
      this.listener?.log?.(
        `device "${this.info.id}" refuses reads of its outputs (${message(e)}): its hold outputs cannot be kept as they are and are written OFF/0 in the safe state`,
      );
      for (const b of this.holdBlocks) for (const p of b.points) seen.set(p.address, zeroOf(p.type));
    }
    for (const [a, v] of seen) this.desired.set(a, v);
    this.holdsUnknown = false;
  }

  private readBackDue(): boolean {
    // Never ahead of a pending safe write: it goes first.
    return this.readBackOn && this.baselineValid && !this.final && !(this.mode === 'safe' && !this.safeAcked);
  }

  /**
   * Reads the outputs back and compares them with what they should be: our last acknowledged write,
   * or (hands off) what was read back last. A difference is another master or the device itself.
   */
  private async readBack(): Promise<void> {
    const client = this.client;
    if (!client) throw new Error('not connected');
    const seen = new Map<string, WireValue>();
    for (const b of this.writeBlocks) {
      const n = b.points.length;
      let raw: readonly (boolean | number)[];
      try {
        if (b.table === 'coils') raw = (await this.request(() => client.readCoils(b.start, n))).data;
        else raw = (await this.request(() => client.readHoldingRegisters(b.start, n))).data;
      } catch (e) {
        if (!isModbusException(e)) throw e;
        this.readBackRefused = message(e);
        return;
      }
      b.points.forEach((p, i) => {
        const r = raw[i];
        seen.set(p.address, typeof r === 'boolean' ? r : fromRegister(p.type, r ?? 0));
      });
    }
    const diffs: [string, WireValue, WireValue][] = [];
    for (const [a, v] of seen) {
      const expected = this.lastSeen.get(a);
      if (expected !== undefined && expected !== v) diffs.push([a, v, expected]);
      this.lastSeen.set(a, v);
    }
    if (diffs.length === 0) return;
    this.foreignChangeAt = Date.now();
    if (this.handsOff) return; // already reported; writing stays stopped
    const [a, v, wrote] = diffs[0]!;
    const more =
      diffs.length > 1 ? `, and ${diffs.length - 1} more output${diffs.length > 2 ? 's' : ''}` : '';
    this.conflictText = `another Modbus master is writing device "${this.info.id}"'s outputs (${a} read back ${onOff(v)}, we wrote ${onOff(wrote)}${more})`;
    this.handsOff = true;
    const wasDriven = this.mode === 'drive';
    this.enterSafe();
    // The hub disarms first, so no `drive` can undo this while the writes below are on the wire.
    this.listener?.otherMaster?.(this.conflictText);
    if (wasDriven) {
      // Switch off only what is still ours: outputs that read back as we drove them and are not safe.
      // Outputs the other master changed are left to it (writing them would be one more flip).
      const zero = safeImage(this.points, this.written, (p) => zeroOf(p.type));
      const changed = new Map<string, WireValue>();
      for (const b of this.writeBlocks) {
        for (const p of b.points) {
          const safe = zero.get(p.address) ?? zeroOf(p.type);
          if (seen.get(p.address) !== this.written.get(p.address) || this.written.get(p.address) === safe)
            continue;
          if (b.table === 'coils') await this.request(() => client.writeCoil(p.register, safe === true));
          else await this.request(() => client.writeRegister(p.register, toRegister(safe)));
          this.written.set(p.address, safe);
          this.lastSeen.set(p.address, safe);
          changed.set(p.address, safe);
        }
      }
      if (changed.size) this.listener?.written(changed);
    }
    // Our part of the outputs is in the safe state; from here on nothing is written until driven again.
    this.writeDue = false;
    this.setSafeAcked(true);
    [...this.ackWaiters].forEach((w) => w());
    this.listener?.status();
  }

  /** Acknowledged or not; while not, status says for how long (every second) and the log says it once when slow. */
  private setSafeAcked(acked: boolean): void {
    const pending = !acked && this.mode === 'safe';
    this.safeAcked = acked;
    if (!pending) {
      if (this.pendingLogged && this.safeSince !== null && acked) {
        this.listener?.log?.(
          `device "${this.info.id}": safe state acknowledged after ${((Date.now() - this.safeSince) / 1000).toFixed(1)} s`,
        );
      }
      this.safeSince = null;
      this.pendingLogged = false;
      clearInterval(this.pendingTimer);
      this.pendingTimer = undefined;
      return;
    }
    this.safeSince ??= Date.now();
    if (this.pendingTimer || this.closed) return;
    this.pendingTimer = setInterval(() => {
      const ms = this.safePendingMs();
      if (ms === null) return;
      if (!this.pendingLogged && ms >= this.cfg.timeoutMs) {
        this.pendingLogged = true;
        this.listener?.log?.(
          `device "${this.info.id}": safe state pending for ${(ms / 1000).toFixed(1)} s (${this.error ?? 'not acknowledged yet'}); each safe write waits up to ${this.cfg.safeWriteTimeoutMs} ms for the device's answer and is retried until acknowledged`,
        );
      }
      this.listener?.status();
    }, 1000);
    this.pendingTimer.unref();
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
      // A silent peer: start over on a fresh connection. Not while the safe image is wanted and its
      // own write has not timed out: a slow device keeps its connection so the safe write is not
      // abandoned to a reconnect (a late reply to an earlier request is matched by its transaction
      // id and dropped).
      const keep = this.mode === 'safe' && !this.final && !this.safeWriteTimedOut;
      if (!keep) {
        this.dropClient();
        this.connectionLost(text);
        this.nextConnectAt = Date.now() + this.backoffMs;
      }
    }
    this.safeWriteTimedOut = false;
    this.offlineIfDue(text);
  }

  /** After FAILED_POLLS_OFFLINE failed polls: offline, inputs stale, and the hub is told (it disarms). */
  private offlineIfDue(text: string): void {
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
