// The browser's WebSocket client for protocol v1: hello/welcome, image/inputs/written/status,
// outputs, stop/arm/resync/simulate, and a reconnect policy. No React; UI subscribes to snapshots.
import {
  gatewayMessageSchema,
  PROTOCOL_VERSION,
  type ClientMessageBody,
  type DeviceInfo,
  type ErrorMessage,
  type GatewayMessage,
  type Role,
  type StatusMessage,
} from '../protocol/messages';
import type { PointInfo, Quality, WireValue } from '../protocol/points';

/** idle: not connected; connecting; open: welcomed; retrying: lost, will reconnect; refused: auth failed, no retry. */
export type LinkState = 'idle' | 'connecting' | 'open' | 'retrying' | 'refused';

export interface GatewayView {
  readonly link: LinkState;
  readonly role: Role | null;
  readonly session: string | null;
  readonly points: readonly PointInfo[];
  readonly devices: readonly DeviceInfo[];
  /** The gateway's fastest device poll (welcome), when it says. */
  readonly pollMs?: number;
  readonly status: StatusMessage | null;
  readonly values: Readonly<Record<string, WireValue>>;
  readonly quality: Readonly<Record<string, Quality>>;
  /** The gateway's last refusal, in its words. */
  readonly lastError: ErrorMessage | null;
  /** Why the link is not open, in plain words (refused token, connection lost...). */
  readonly problem: string | null;
}

/** The view of a client that is not connected. */
export const IDLE_VIEW: GatewayView = {
  link: 'idle',
  role: null,
  session: null,
  points: [],
  devices: [],
  status: null,
  values: {},
  quality: {},
  lastError: null,
  problem: null,
};

/** The subset of the browser WebSocket the client uses (Node tests pass the `ws` package's class). */
export interface SocketLike {
  readonly readyState: number;
  onopen: ((ev: unknown) => void) | null;
  onmessage: ((ev: { data: unknown }) => void) | null;
  onclose: ((ev: { code: number; reason: string }) => void) | null;
  onerror: ((ev: unknown) => void) | null;
  send(data: string): void;
  close(code?: number, reason?: string): void;
}
export type SocketFactory = (url: string) => SocketLike;

export interface GatewayClientOptions {
  /** ws://127.0.0.1:8080/io */
  readonly socketUrl: string;
  readonly token: string;
  readonly role: Role;
  readonly socketFactory?: SocketFactory;
  /** First reconnect delay; doubles up to `retryMaxMs`. */
  readonly retryFirstMs?: number;
  readonly retryMaxMs?: number;
}

const OPEN = 1;

export class GatewayClient {
  private view: GatewayView = IDLE_VIEW;
  private socket: SocketLike | undefined;
  private readonly listeners = new Set<(v: GatewayView) => void>();
  private readonly messageListeners = new Set<(m: GatewayMessage) => void>();
  private seq = 0;
  private retryMs: number;
  private retryTimer: ReturnType<typeof setTimeout> | undefined;
  private wanted = false;

  constructor(private readonly opts: GatewayClientOptions) {
    this.retryMs = opts.retryFirstMs ?? 500;
  }

  get snapshot(): GatewayView {
    return this.view;
  }

  /** Subscribe to view changes (for useSyncExternalStore); returns the unsubscribe function. */
  subscribe(listener: (v: GatewayView) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Every validated gateway message, in order. */
  onMessage(listener: (m: GatewayMessage) => void): () => void {
    this.messageListeners.add(listener);
    return () => this.messageListeners.delete(listener);
  }

  connect(): void {
    this.wanted = true;
    clearTimeout(this.retryTimer);
    this.open();
  }

  disconnect(): void {
    this.wanted = false;
    clearTimeout(this.retryTimer);
    const s = this.socket;
    this.socket = undefined;
    s?.close(1000, 'disconnect');
    this.update({ ...IDLE_VIEW });
  }

  get isController(): boolean {
    return this.view.link === 'open' && this.view.role === 'controller';
  }

  /** The output image of one scan (also the lease heartbeat). Returns false when not sent (not the controller). */
  sendOutputs(values: Readonly<Record<string, WireValue>>): boolean {
    if (!this.isController) return false;
    return this.send({ t: 'outputs', seq: ++this.seq, values: { ...values } });
  }
  stop(): boolean {
    return this.isController && this.send({ t: 'stop', seq: ++this.seq });
  }
  arm(): boolean {
    return this.isController && this.send({ t: 'arm', seq: ++this.seq });
  }
  resync(): boolean {
    return this.send({ t: 'resync', seq: ++this.seq });
  }
  /** Sets inputs of the gateway's simulated device (any role). */
  simulate(values: Readonly<Record<string, WireValue>>): boolean {
    return this.send({ t: 'simulate', seq: ++this.seq, values: { ...values } });
  }

  private send(body: ClientMessageBody): boolean {
    const s = this.socket;
    if (!s || s.readyState !== OPEN || this.view.link !== 'open') return false;
    s.send(JSON.stringify({ v: PROTOCOL_VERSION, ...body }));
    return true;
  }

  private open(): void {
    const factory: SocketFactory = this.opts.socketFactory ?? ((url) => new WebSocket(url) as unknown as SocketLike);
    let s: SocketLike;
    try {
      s = factory(this.opts.socketUrl);
    } catch (e) {
      this.lost(`cannot open ${this.opts.socketUrl}: ${(e as Error).message}`);
      return;
    }
    this.socket = s;
    this.update({ ...this.view, link: 'connecting', problem: null });
    s.onopen = () => s.send(JSON.stringify({ v: PROTOCOL_VERSION, t: 'hello', token: this.opts.token, role: this.opts.role }));
    s.onmessage = (ev) => {
      if (this.socket === s && typeof ev.data === 'string') this.receive(ev.data);
    };
    s.onerror = () => undefined; // the close event follows with the reason
    s.onclose = (ev) => {
      if (this.socket !== s) return;
      this.socket = undefined;
      if (ev.code === 1008) {
        this.wanted = false;
        const why = this.view.lastError?.message ?? ev.reason;
        const wasController = this.view.role === 'controller';
        const problem =
          this.view.lastError?.code === 'flood'
            ? `the gateway closed the link: this page sent ${why} (flood protection)${wasController ? '; the program no longer drives the outputs, the gateway holds them in the safe state' : ''}. Press Reconnect`
            : `refused by the gateway: ${why || 'policy violation'}`;
        this.update({ ...IDLE_VIEW, link: 'refused', lastError: this.view.lastError, problem });
        return;
      }
      this.lost(ev.code === 1006 ? `no gateway at ${this.opts.socketUrl}` : `connection closed (${ev.code}${ev.reason ? `: ${ev.reason}` : ''})`);
    };
  }

  private lost(problem: string): void {
    if (!this.wanted) {
      this.update({ ...IDLE_VIEW, problem });
      return;
    }
    const wait = this.retryMs;
    this.retryMs = Math.min(this.retryMs * 2, this.opts.retryMaxMs ?? 10_000);
    this.update({ ...this.view, link: 'retrying', role: null, problem: `${problem}; retrying in ${Math.round(wait / 100) / 10} s` });
    this.retryTimer = setTimeout(() => this.wanted && this.open(), wait);
  }

  private receive(text: string): void {
    let msg: GatewayMessage;
    try {
      const parsed = gatewayMessageSchema.safeParse(JSON.parse(text));
      if (!parsed.success) return; // a newer gateway's extra message types are ignored
      msg = parsed.data;
    } catch {
      return;
    }
    const v = this.view;
    switch (msg.t) {
      case 'welcome':
        this.retryMs = this.opts.retryFirstMs ?? 500;
        this.update({ ...v, link: 'open', role: msg.role, session: msg.session, points: msg.points, devices: msg.devices, pollMs: msg.pollMs, problem: null });
        break;
      case 'image':
        this.update({ ...v, values: msg.values, quality: msg.quality });
        break;
      case 'inputs':
        this.update({ ...v, values: { ...v.values, ...msg.values }, quality: { ...v.quality, ...msg.quality } });
        break;
      case 'written': {
        const quality = { ...v.quality };
        for (const a of Object.keys(msg.values)) quality[a] = 'good';
        this.update({ ...v, values: { ...v.values, ...msg.values }, quality });
        break;
      }
      case 'status': {
        // Armed again: refusals of the disarmed state are history.
        const stale = msg.armed && (v.lastError?.code === 'disarmed' || v.lastError?.code === 'arm-refused');
        this.update({ ...v, status: msg, ...(stale ? { lastError: null } : {}) });
        break;
      }
      case 'error':
        this.update({ ...v, lastError: msg });
        break;
    }
    this.messageListeners.forEach((l) => l(msg));
  }

  private update(next: GatewayView): void {
    this.view = next;
    this.listeners.forEach((l) => l(next));
  }
}
