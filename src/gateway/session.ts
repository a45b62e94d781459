// One WebSocket client: hello/auth, validation of every message, dispatch to the hub.
import type { WebSocket } from 'ws';
import {
  clientMessageSchema,
  describeIssues,
  MAX_FRAME_BYTES,
  PROTOCOL_VERSION,
  type ClientMessage,
  type ErrorCode,
  type GatewayMessageBody,
  type Role,
} from '../protocol/messages';
import type { IoHub } from './ioHub';
import { RateLimiter, tokenMatches, type StallMeter } from './security';
import type { SimulatedDevice } from './simulatedDevice';

export const MESSAGES_PER_SECOND = 200;
/**
 * `resync` asks for the whole image (thousands of points on a large map): answered at most this
 * often per client, with a burst of RESYNC_BURST; more get a polite `too-often` refusal, and the
 * client's view stays current anyway through `inputs` and `written`.
 */
export const RESYNCS_PER_SECOND = 4;
export const RESYNC_BURST = 8;
/** A socket that has not said hello by then is closed (1008): silent sockets cannot hold the connection slots. */
export const HELLO_TIMEOUT_MS = 1500;
/** Close code when the last connection, kept for a controller, is asked for by an observer. */
export const TRY_AGAIN_LATER = 1013;
/** Close code for policy violations: auth failures and floods. */
export const POLICY_VIOLATION = 1008;

export interface SessionContext {
  readonly hub: IoHub;
  readonly token: string;
  readonly simulated: SimulatedDevice | undefined;
  nextSeq(): number;
  log(line: string): void;
  /** The message budget, carried over from this client's previous connection (security.ts MessageBudgets). */
  readonly limiter?: RateLimiter;
  /** False when one more observer would take the last connection, which is kept for a controller. */
  mayObserve?(): boolean;
  /** Event-loop stalls: their backlog is not counted as a flood (security.ts StallMeter). */
  readonly stalls?: StallMeter;
  /** The full image as one serialised frame, cached until the image changes (gateway.ts). */
  imageFrame?(seq: number): string;
  /** The fastest device poll (ms), told to clients in the welcome. */
  readonly pollMs?: number;
}

export class Session {
  role: Role | null = null;
  private readonly limiter: RateLimiter;
  private readonly resyncs = new RateLimiter(RESYNCS_PER_SECOND, RESYNC_BURST);
  private readonly helloTimer: NodeJS.Timeout;
  private closed = false;
  private silenced = false;

  constructor(
    readonly id: string,
    private readonly ws: WebSocket,
    private readonly ctx: SessionContext,
  ) {
    this.limiter = ctx.limiter ?? new RateLimiter(MESSAGES_PER_SECOND);
    this.helloTimer = setTimeout(() => this.refuseAndClose('not-hello', `no hello within ${HELLO_TIMEOUT_MS / 1000} s`, null), HELLO_TIMEOUT_MS);
    ws.on('message', (data, isBinary) => {
      try {
        this.receive(data as Buffer | Buffer[] | ArrayBuffer, isBinary);
      } catch (e) {
        // A bug must cost one message, not the gateway: refuse it and keep serving.
        this.ctx.log(`session ${this.id}: internal error: ${e instanceof Error ? (e.stack ?? e.message) : String(e)}`);
        this.refuse('bad-message', 'the gateway could not handle this message', null);
      }
    });
    ws.on('close', () => this.closeDown());
    ws.on('error', () => this.closeDown()); // oversized frames and socket errors must not crash the gateway
  }

  send(body: GatewayMessageBody): void {
    if (this.closed || this.ws.readyState !== this.ws.OPEN) return;
    this.sendText(JSON.stringify({ v: PROTOCOL_VERSION, ...body }));
  }

  private sendText(text: string): void {
    if (this.closed || this.ws.readyState !== this.ws.OPEN) return;
    // A client that stopped reading is dropped rather than buffered without bound.
    if (this.ws.bufferedAmount > 8 * 1024 * 1024) {
      this.ws.close(1013, 'client too slow');
      return;
    }
    this.ws.send(text);
  }

  private sendImage(): void {
    const seq = this.ctx.nextSeq();
    if (this.ctx.imageFrame) this.sendText(this.ctx.imageFrame(seq));
    else this.send({ t: 'image', seq, ...this.ctx.hub.image() });
  }

  /** Closed, or closing: holds no connection slot any more. */
  get isClosed(): boolean {
    return this.closed;
  }

  /**
   * A socket that has not said hello gives its place to a newer one (too many are waiting): a
   * client that says hello at once always gets in, however many silent sockets are open.
   */
  evict(): void {
    if (this.role !== null || this.closed) return;
    this.refuse('not-hello', 'too many connections are waiting for hello; this one waited longest', null);
    this.ws.close(TRY_AGAIN_LATER, 'too many connections waiting for hello');
    this.closeDown();
  }

  private refuse(code: ErrorCode, message: string, ref: number | string | null): void {
    this.send({ t: 'error', code, message, ref });
  }

  private refuseAndClose(code: ErrorCode, message: string, ref: number | string | null): void {
    this.refuse(code, message, ref);
    this.ws.close(POLICY_VIOLATION, message.slice(0, 120));
    this.closeDown();
  }

  private receive(data: Buffer | Buffer[] | ArrayBuffer, isBinary: boolean): void {
    if (this.closed || this.silenced) return;
    if (!this.limiter.takeWithCredit(this.ctx.stalls?.creditMs() ?? 0)) {
      this.ctx.log(`session ${this.id}: closed for flooding (over ${MESSAGES_PER_SECOND} messages/s)`);
      this.refuseAndClose('flood', `more than ${MESSAGES_PER_SECOND} messages per second`, null);
      return;
    }
    const buf = Buffer.isBuffer(data) ? data : Array.isArray(data) ? Buffer.concat(data) : Buffer.from(data);
    if (buf.length > MAX_FRAME_BYTES) {
      this.refuse('too-large', `frame of ${buf.length} bytes is over the 64 KiB limit`, null);
      return;
    }
    if (isBinary) {
      this.refuse('bad-message', 'binary frames are not part of the protocol; send JSON text', null);
      return;
    }
    let raw: unknown;
    try {
      raw = JSON.parse(buf.toString('utf8'), noPrototypeKeys);
    } catch (e) {
      if (e instanceof PrototypeKeyError) this.refuse('bad-message', e.message, null);
      else this.refuse('bad-json', 'the frame is not valid JSON', null);
      return;
    }
    const ref = refOf(raw);
    const parsed = clientMessageSchema.safeParse(raw);
    if (this.role === null) {
      this.helloStep(parsed.success ? parsed.data : undefined, raw, ref);
      return;
    }
    if (!parsed.success) {
      this.refuse('bad-message', explain(raw, describeIssues(parsed.error)), ref);
      return;
    }
    this.dispatch(parsed.data, ref).catch((e: unknown) => {
      this.ctx.log(`session ${this.id}: ${parsed.data.t} failed: ${e instanceof Error ? e.message : String(e)}`);
    });
  }

  private helloStep(msg: ClientMessage | undefined, raw: unknown, ref: number | string | null): void {
    if (!msg || msg.t !== 'hello') {
      const why = msg ? `"${msg.t}" before "hello"` : explain(raw, 'not a valid hello');
      this.refuseAndClose('not-hello', `send hello with token and role first (${why})`, ref);
      return;
    }
    if (!tokenMatches(this.ctx.token, msg.token)) {
      this.ctx.log(`session ${this.id}: refused, wrong token`);
      this.refuseAndClose('bad-token', 'wrong token: open the URL the gateway printed (…/#token=…)', 'hello');
      return;
    }
    clearTimeout(this.helloTimer);
    const hub = this.ctx.hub;
    const role = hub.claim(this.id, msg.role);
    if (role !== 'controller' && this.ctx.mayObserve?.() === false) {
      // The last free connection is kept for a controller, so one that reconnects always gets in.
      this.ctx.log(`session ${this.id}: refused as observer, the last connection is kept for a controller`);
      this.refuse('not-controller', 'the last free connection is kept for a controller; try again later', 'hello');
      this.ws.close(TRY_AGAIN_LATER, 'the last connection is kept for a controller');
      this.closeDown();
      return;
    }
    this.role = role;
    this.ctx.log(`session ${this.id}: ${this.role}${msg.role !== this.role ? ' (controller lease is taken)' : ''}`);
    this.send({ t: 'welcome', session: this.id, role: this.role, points: hub.pointList(), devices: hub.devices.map((d) => d.info), ...(this.ctx.pollMs ? { pollMs: this.ctx.pollMs } : {}) });
    this.sendImage();
    this.send({ t: 'status', ...hub.status() });
  }

  private async dispatch(msg: ClientMessage, ref: number | string | null): Promise<void> {
    const hub = this.ctx.hub;
    switch (msg.t) {
      case 'hello':
        this.refuse('already-hello', 'this session already said hello', ref);
        return;
      case 'resync':
        if (!this.resyncs.take()) {
          this.refuse('too-often', `resync is answered at most ${RESYNCS_PER_SECOND} times per second; inputs and written keep the image current meanwhile`, ref);
          return;
        }
        this.sendImage();
        return;
      case 'simulate': {
        if (!this.ctx.simulated) {
          this.refuse('not-simulated', 'this gateway has no simulated device; inputs come from the field', ref);
          return;
        }
        const checked = hub.check(msg.values, 'in', true);
        if (!(checked instanceof Map)) return this.refuse(checked.code, checked.message, ref);
        for (const address of checked.keys()) {
          const sensor = this.ctx.simulated.machineSensorRefusal(address);
          if (sensor) return this.refuse('not-input', sensor, ref);
        }
        this.ctx.simulated.simulateInputs(checked);
        return;
      }
      case 'outputs':
      case 'stop':
      case 'arm':
        break;
    }
    if (!hub.isController(this.id)) {
      this.refuse('not-controller', `"${msg.t}" needs the controller lease; this session is an observer`, ref);
      return;
    }
    if (msg.t === 'stop') return hub.stop('the controller sent stop');
    if (msg.t === 'arm') {
      const refused = hub.arm();
      if (refused) this.refuse(refused.code, refused.message, ref);
      return;
    }
    const checked = hub.check(msg.values, 'out', false);
    if (!(checked instanceof Map)) return this.refuse(checked.code, checked.message, ref);
    const result = hub.outputs(checked);
    if (result === 'disarmed') this.refuse('disarmed', `outputs refused: ${hub.disarmReason()}`, ref);
    else if (result === 'shutting-down') this.refuse('shutting-down', 'the gateway is shutting down; outputs are in the safe state', ref);
  }

  /** Shutdown: no message is dispatched any more (the safe write must be the last write). */
  silence(): void {
    this.silenced = true;
  }

  private closeDown(): void {
    if (this.closed) return;
    this.closed = true;
    clearTimeout(this.helloTimer);
    void this.ctx.hub.release(this.id);
  }
}

class PrototypeKeyError extends Error {}

/** Keys that would rewrite an object's prototype once copied are refused outright. */
function noPrototypeKeys(key: string, value: unknown): unknown {
  if (key === '__proto__' || key === 'constructor' || key === 'prototype') throw new PrototypeKeyError(`key "${key}" is not allowed`);
  return value;
}

function refOf(raw: unknown): number | string | null {
  if (typeof raw !== 'object' || raw === null) return null;
  const r = raw as { seq?: unknown; t?: unknown };
  if (typeof r.seq === 'number' && Number.isFinite(r.seq)) return r.seq;
  if (typeof r.t === 'string') return r.t.slice(0, 32);
  return null;
}

function explain(raw: unknown, detail: string): string {
  if (typeof raw !== 'object' || raw === null || Array.isArray(raw)) return 'a message is a JSON object {"v":1,"t":...}';
  const r = raw as { v?: unknown; t?: unknown };
  if (r.v !== PROTOCOL_VERSION) return `protocol version ${JSON.stringify(r.v)} is not supported; this gateway speaks v1`;
  if (typeof r.t !== 'string') return 'missing message type "t"';
  if (!['hello', 'outputs', 'stop', 'arm', 'resync', 'simulate'].includes(r.t)) return `unknown message type "${r.t.slice(0, 32)}"`;
  return `bad "${r.t}": ${detail}`;
}
