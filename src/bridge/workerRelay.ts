/**
 * GatewayRelay: the gateway link's end inside the simulation worker (issue 21 item 5).
 *
 * Why here: the gateway's lease is fed by the controller's `outputs`; when they came from the page's
 * main thread, any 1 s stall of the page (a busy machine, a long render, a GC) tripped a running
 * controller. The worker runs the scan, so the worker holds the WebSocket and, while the page drives
 * the hardware, sends the outputs and the heartbeat itself:
 *   - a busy page does not trip the lease (the worker keeps scanning and sending);
 *   - a stopped program does (a `run` drive ends when the program stops running: `stop` is sent at
 *     once), and so does a hung or terminated worker (nothing is sent; its socket closes);
 *   - inputs go from the socket straight into the program's input image, without the page.
 * The page keeps the protocol logic (GatewayClient: hello, view, arm, stop, resync) and reaches the
 * socket through gwOpen/gwSend/gwClose (src/bridge/workerSocket.ts), so one connection, one lease.
 * `arm` sent before gwDrive is on the socket before the first outputs (one ordered queue).
 */
import type { Value } from '../model/iecTypes';
import { PROTOCOL_VERSION } from '../protocol/messages';
import { canonicalAddress, zeroOf, type PointType, type WireValue } from '../protocol/points';
import type { GatewayDrive, GatewayHostMessage, GatewayWorkerMessage, SimFrame } from '../sim/protocol';
import type { SocketLike } from './GatewayClient';
import { OutputPump } from './outputPump';
import { fromWire, toWire } from './wireValues';

/** What the relay needs of the simulation running next to it. */
export interface RelaySimulation {
  /** Gateway inputs by IEC location, applied at the next input read. */
  setInputs(values: Readonly<Record<string, Value>>): void;
  /** Output images wanted (outputs(...) called after every scan that changed them) or not. */
  wantOutputs(on: boolean): void;
}

interface Link {
  readonly id: number;
  readonly socket: SocketLike;
  role: string | null;
  pollMs: number | undefined;
  /** Output point types by address (from the welcome). */
  outTypes: Map<string, PointType>;
  /** Outputs configured `hold` (from the welcome): their safe value is their last value. */
  holds: Set<string>;
  values: Record<string, WireValue>;
  /**
   * Outputs written through this link since the gateway last disarmed (it then writes the safe
   * image itself). One the program shown no longer writes, after an online change moved or removed
   * its variable, is given its safe value: OFF/0 (the gateway keeps the last value of a point it is
   * not sent, so it would stay ON with no program switching it off), or, configured `hold`, its last
   * value (a valve that must not move when no program drives it, as in the safe state).
   */
  driven: Map<string, PointType>;
}

const OPEN = 1;

export class GatewayRelay {
  private readonly links = new Map<number, Link>();
  /** The link the page opened last: the one a drive uses. */
  private current: Link | undefined;
  private drive: (GatewayDrive & { readonly link: Link }) | undefined;
  private programs = new Set<string>();
  private mode: SimFrame['mode'] | undefined;
  private image: Record<string, WireValue> = {};
  /** The program the image being sent came from. */
  private imageOf: string | undefined;
  /** The relay's own outputs numbering, apart from the page's messages. */
  private seq = 1_000_000_000;
  private readonly pump: OutputPump;

  constructor(
    private readonly post: (message: GatewayWorkerMessage) => void,
    private readonly socketFactory: (url: string) => SocketLike,
    private readonly sim: RelaySimulation,
  ) {
    this.pump = new OutputPump((image) => this.sendOutputs(image), { periodMs: () => this.drive?.link.pollMs ?? 100 });
  }

  get driving(): boolean {
    return this.drive !== undefined;
  }

  /** Handles the page's gw* messages. */
  handle(m: GatewayHostMessage): void {
    switch (m.type) {
      case 'gwOpen':
        this.open(m.id, m.url);
        return;
      case 'gwSend': {
        const link = this.links.get(m.id);
        if (link && link.socket.readyState === OPEN) link.socket.send(m.data);
        return;
      }
      case 'gwClose': {
        const link = this.links.get(m.id);
        this.links.delete(m.id);
        if (link === this.drive?.link) this.endDrive(null);
        if (link === this.current) this.current = undefined;
        link?.socket.close(m.code, m.reason);
        return;
      }
      case 'gwDrive':
        if (m.drive) this.startDrive(m.drive);
        else this.endDrive(null);
        return;
      case 'gwPrograms':
        this.programs = new Set(m.ids);
        // The program whose image is being sent is no longer the one shown: its image is not re-sent
        // as a heartbeat (the page stops the worker; meanwhile the watchdog guards).
        if (this.imageOf !== undefined && !this.programs.has(this.imageOf)) {
          this.pump.stop();
          this.image = {};
          this.imageOf = undefined;
        }
        return;
    }
  }

  /** Every frame the simulation posts: a `run` drive ends when the program stops running. */
  frame(frame: SimFrame): void {
    const was = this.mode;
    this.mode = frame.mode;
    if (this.drive?.kind === 'run' && was === 'running' && frame.mode !== 'running') {
      const why = frame.mode === 'faulted' ? 'the program faulted' : frame.mode === 'paused' ? 'the program paused' : 'the program stopped';
      this.endDrive(`${why}: the gateway was told to write the safe state`);
    }
  }

  /** The output image after a scan that changed it, from program `program`. */
  outputs(outputs: Readonly<Record<string, Value>>, program: string): void {
    const drive = this.drive;
    if (!drive || !this.programs.has(program)) return; // only the program shown drives the outputs
    const next: Record<string, WireValue> = { ...this.image };
    const written = new Set<string>();
    for (const [text, value] of Object.entries(outputs)) {
      const address = canonicalAddress(text);
      const type = address ? drive.link.outTypes.get(address) : undefined;
      if (address && type) {
        next[address] = toWire(type, value);
        written.add(address);
      }
    }
    // `outputs` is the program's whole output image: a point driven before and missing now is no
    // longer its output, and takes its safe value (a `hold` point keeps the value it has: `next` holds it).
    for (const [address, type] of drive.link.driven) if (!written.has(address) && !drive.link.holds.has(address)) next[address] = zeroOf(type);
    for (const address of written) drive.link.driven.set(address, drive.link.outTypes.get(address)!);
    this.image = next;
    this.imageOf = program;
    this.pump.offer(next);
  }

  private open(id: number, url: string): void {
    let socket: SocketLike;
    try {
      socket = this.socketFactory(url);
    } catch (e) {
      this.post({ type: 'gwEvent', id, event: 'close', code: 1006, reason: e instanceof Error ? e.message : String(e) });
      return;
    }
    const link: Link = { id, socket, role: null, pollMs: undefined, outTypes: new Map(), holds: new Set(), values: {}, driven: new Map() };
    this.links.set(id, link);
    this.current = link;
    socket.onopen = () => this.post({ type: 'gwEvent', id, event: 'open' });
    socket.onerror = () => undefined; // the close event follows
    socket.onmessage = (ev) => {
      if (typeof ev.data !== 'string') return;
      this.observe(link, ev.data);
      this.post({ type: 'gwEvent', id, event: 'message', data: ev.data });
    };
    socket.onclose = (ev) => {
      this.links.delete(id);
      if (this.current === link) this.current = undefined;
      if (this.drive?.link === link) this.endDrive(null, 'the link to the gateway closed: the program no longer drives the outputs');
      this.post({ type: 'gwEvent', id, event: 'close', code: ev.code, reason: ev.reason });
    };
  }

  /** What the relay needs from the gateway's messages: role, point types, input values. */
  private observe(link: Link, text: string): void {
    let m: { t?: unknown; role?: unknown; pollMs?: unknown; points?: unknown; values?: unknown; armed?: unknown };
    try {
      m = JSON.parse(text) as typeof m;
    } catch {
      return;
    }
    if (m.t === 'welcome') {
      link.role = typeof m.role === 'string' ? m.role : null;
      link.pollMs = typeof m.pollMs === 'number' ? m.pollMs : undefined;
      link.outTypes = new Map();
      link.holds = new Set();
      if (Array.isArray(m.points)) {
        for (const p of m.points as { address?: unknown; type?: unknown; dir?: unknown; hold?: unknown }[]) {
          if (typeof p.address === 'string' && p.dir === 'out') link.outTypes.set(p.address, p.type as PointType);
          if (typeof p.address === 'string' && p.dir === 'out' && p.hold === true) link.holds.add(p.address);
        }
      }
    } else if (m.t === 'status' && m.armed === false) {
      link.driven.clear(); // disarmed: the gateway holds every output in the safe state
    } else if ((m.t === 'image' || m.t === 'inputs' || m.t === 'written') && m.values && typeof m.values === 'object') {
      const values = m.values as Record<string, WireValue>;
      link.values = m.t === 'image' ? { ...values } : { ...link.values, ...values };
      if (this.drive?.link === link && m.t !== 'written') this.applyInputs(values);
    }
  }

  private applyInputs(values: Readonly<Record<string, WireValue>>): void {
    const drive = this.drive;
    if (!drive) return;
    const typed: Record<string, Value> = {};
    for (const b of drive.bindings) {
      const v = values[b.address];
      if (b.dir === 'in' && v !== undefined) typed[b.address] = fromWire(b.varType, v);
    }
    if (Object.keys(typed).length) this.sim.setInputs(typed);
  }

  private startDrive(drive: GatewayDrive): void {
    const link = this.current;
    if (!link) {
      this.post({ type: 'gwDriveEnded', reason: 'no link to the gateway: the program does not drive the outputs' });
      return;
    }
    this.pump.stop();
    this.image = {};
    this.drive = { ...drive, link };
    this.applyInputs(link.values);
    // The simulation reports its current output image at once, so the first outputs (and the
    // heartbeat) start right away.
    this.sim.wantOutputs(true);
  }

  /** Ends the drive; with `stopReason` also tells the gateway `stop` (safe state) and the page why. */
  private endDrive(stopReason: string | null, lostReason?: string): void {
    const drive = this.drive;
    if (!drive) return;
    this.drive = undefined;
    this.pump.stop();
    this.image = {};
    this.sim.wantOutputs(false);
    if (stopReason && drive.link.socket.readyState === OPEN && drive.link.role === 'controller') {
      drive.link.socket.send(JSON.stringify({ v: PROTOCOL_VERSION, t: 'stop', seq: ++this.seq }));
    }
    const reason = stopReason ?? lostReason;
    if (reason) this.post({ type: 'gwDriveEnded', reason });
  }

  private sendOutputs(image: Readonly<Record<string, WireValue>>): boolean {
    const link = this.drive?.link;
    if (!link || link.role !== 'controller' || link.socket.readyState !== OPEN) return false;
    link.socket.send(JSON.stringify({ v: PROTOCOL_VERSION, t: 'outputs', seq: ++this.seq, values: image }));
    return true;
  }
}
