// Real peers for gateway tests: Debian's pymodbus server, mbpoll, and a ws client speaking protocol v1.
import { execFile, spawn, type ChildProcessWithoutNullStreams } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { connect, createServer as createNetServer, type AddressInfo, type Server, type Socket } from 'node:net';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';
import WebSocket from 'ws';
import { gatewayMessageSchema, type GatewayMessage } from '../../src/protocol/messages';

const SERVER_SCRIPT = fileURLToPath(new URL('./fixtures/modbus_server.py', import.meta.url));

export type Table = 'di' | 'co' | 'ir' | 'hr';

/** Debian's python3-pymodbus Modbus TCP server on a loopback port, driven over stdin. */
export class PyModbusServer {
  private readonly lines: string[] = [];
  private waiters: ((line: string) => void)[] = [];
  private constructor(
    readonly port: number,
    private readonly proc: ChildProcessWithoutNullStreams,
  ) {
    createInterface({ input: proc.stdout }).on('line', (line) => {
      const w = this.waiters.shift();
      if (w) w(line);
      else this.lines.push(line);
    });
    proc.stderr.resume();
  }

  /** @param writeLog file that gets one line per client write (see readWriteLog), kept across restarts. */
  static async start(port: number, writeLog?: string): Promise<PyModbusServer> {
    const proc = spawn('/usr/bin/python3', [SERVER_SCRIPT, String(port), ...(writeLog ? [writeLog] : [])], { stdio: ['pipe', 'pipe', 'pipe'] });
    const server = new PyModbusServer(port, proc);
    const first = await server.nextLine(10_000);
    if (first !== 'READY') throw new Error(`pymodbus server did not start: ${first}`);
    return server;
  }

  private nextLine(timeoutMs = 5000): Promise<string> {
    const queued = this.lines.shift();
    if (queued !== undefined) return Promise.resolve(queued);
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error('pymodbus server did not answer')), timeoutMs);
      this.waiters.push((line) => {
        clearTimeout(timer);
        resolve(line);
      });
    });
  }

  async set(table: Table, address: number, values: readonly number[]): Promise<void> {
    this.proc.stdin.write(`set ${table} ${address} ${values.join(' ')}\n`);
    const r = await this.nextLine();
    if (r !== 'OK') throw new Error(r);
  }

  async get(table: Table, address: number, count: number): Promise<number[]> {
    this.proc.stdin.write(`get ${table} ${address} ${count}\n`);
    const r = await this.nextLine();
    const m = /^\w+ \d+ ([\d,-]+)$/.exec(r);
    if (!m?.[1]) throw new Error(r);
    return m[1].split(',').map(Number);
  }

  /** Fault injection: answer normally, with a Modbus exception, or only after `delayMs`. */
  async mode(mode: 'normal' | 'exception' | 'slow', delayMs = 0): Promise<void> {
    this.proc.stdin.write(`mode ${mode} ${delayMs}\n`);
    const r = await this.nextLine(10_000);
    if (r !== 'OK') throw new Error(r);
  }

  get alive(): boolean {
    return this.proc.exitCode === null && this.proc.signalCode === null;
  }

  kill(): Promise<void> {
    if (this.proc.exitCode !== null || this.proc.signalCode !== null) return Promise.resolve();
    return new Promise((resolve) => {
      this.proc.once('exit', () => resolve());
      this.proc.kill('SIGKILL');
    });
  }
}

/** One write a client made to the pymodbus server, from its write log. */
export interface LoggedWrite {
  readonly at: number;
  readonly table: 'co' | 'hr';
  readonly address: number;
  readonly values: readonly number[];
}

/** The writes in a pymodbus write log, in order. */
export function readWriteLog(file: string): LoggedWrite[] {
  if (!existsSync(file)) return [];
  return readFileSync(file, 'utf8')
    .split('\n')
    .filter((l) => l.trim() !== '')
    .map((l) => {
      const [at, table, address, values] = l.split(' ');
      return { at: Number(at), table: table as 'co' | 'hr', address: Number(address), values: (values ?? '').split(',').map(Number) };
    });
}

/** Runs Debian's mbpoll once (zero-based references) and returns its stdout. */
export function mbpoll(port: number, args: readonly string[]): Promise<string> {
  return new Promise((resolve, reject) => {
    execFile('mbpoll', ['-m', 'tcp', '-a', '1', '-0', '-1', '-p', String(port), ...args], { timeout: 10_000 }, (err, stdout, stderr) => {
      if (err) reject(new Error(`mbpoll failed: ${stderr || err.message}`));
      else resolve(stdout);
    });
  });
}

/** Values printed by `mbpoll` for a read, as numbers in reference order. */
export function mbpollValues(stdout: string): number[] {
  return [...stdout.matchAll(/^\[\d+\]:\s+(-?\d+)/gm)].map((m) => Number(m[1]));
}

/** A protocol v1 client over a real WebSocket, recording every gateway message. */
export class TestClient {
  readonly messages: GatewayMessage[] = [];
  readonly invalid: string[] = [];
  closeCode: number | undefined;
  private listeners: (() => void)[] = [];
  private constructor(readonly ws: WebSocket) {
    ws.on('message', (data) => {
      const text = (data as Buffer).toString();
      const parsed = gatewayMessageSchema.safeParse(JSON.parse(text));
      if (parsed.success) this.messages.push(parsed.data);
      else this.invalid.push(text);
      this.listeners.forEach((l) => l());
    });
    ws.on('close', (code) => {
      this.closeCode = code;
      this.listeners.forEach((l) => l());
    });
    ws.on('error', () => undefined);
  }

  static connect(port: number, headers: Record<string, string> = {}): Promise<TestClient> {
    return new Promise((resolve, reject) => {
      const ws = new WebSocket(`ws://127.0.0.1:${port}/io`, { headers });
      const client = new TestClient(ws);
      ws.once('open', () => resolve(client));
      ws.once('unexpected-response', (_req, res) => reject(new Error(`HTTP ${res.statusCode}`)));
      ws.once('error', reject);
    });
  }

  static async hello(port: number, token: string, role: 'controller' | 'observer'): Promise<TestClient> {
    const c = await TestClient.connect(port);
    c.send({ t: 'hello', token, role });
    await c.waitFor((m) => m.t === 'status');
    return c;
  }

  /**
   * A controller that has armed the outputs (the gateway starts disarmed): waits until every device
   * is online, sends `arm` and waits for the armed status.
   */
  static async armedController(port: number, token: string): Promise<TestClient> {
    const c = await TestClient.hello(port, token, 'controller');
    await c.arm();
    return c;
  }

  /** Sends `arm` once every device is online and resolves when the gateway says it is armed. */
  async arm(timeoutMs = 5000): Promise<void> {
    await this.waitFor((m) => m.t === 'status' && m.devices.every((d) => d.state === 'online'), timeoutMs);
    const from = this.messages.length;
    this.send({ t: 'arm' });
    await this.waitFor((m) => (m.t === 'status' && m.armed) || (m.t === 'error' && m.code === 'arm-refused'), timeoutMs, from).then((m) => {
      if (m.t === 'error') throw new Error(`arm refused: ${m.message}`);
    });
  }

  /** The newest status message. */
  lastStatus(): Extract<GatewayMessage, { t: 'status' }> | undefined {
    for (let i = this.messages.length - 1; i >= 0; i--) {
      const m = this.messages[i];
      if (m?.t === 'status') return m;
    }
    return undefined;
  }

  send(body: Record<string, unknown>): void {
    this.ws.send(JSON.stringify({ v: 1, ...body }));
  }

  sendRaw(data: string | Buffer): void {
    this.ws.send(data);
  }

  /** Resolves with the first message (from `from` on) matching `pred`. */
  waitFor<T extends GatewayMessage>(pred: (m: GatewayMessage) => m is T, timeoutMs?: number, from?: number): Promise<T>;
  waitFor(pred: (m: GatewayMessage) => boolean, timeoutMs?: number, from?: number): Promise<GatewayMessage>;
  waitFor(pred: (m: GatewayMessage) => boolean, timeoutMs = 5000, from = 0): Promise<GatewayMessage> {
    return new Promise((resolve, reject) => {
      const check = () => {
        const found = this.messages.slice(from).find(pred);
        if (found) {
          done();
          resolve(found);
        } else if (this.closeCode !== undefined) {
          done();
          reject(new Error(`connection closed (${this.closeCode}) before the expected message`));
        }
      };
      const timer = setTimeout(() => {
        done();
        reject(new Error(`no matching message within ${timeoutMs} ms; last: ${JSON.stringify(this.messages.slice(-3))}`));
      }, timeoutMs);
      const done = () => {
        clearTimeout(timer);
        this.listeners = this.listeners.filter((l) => l !== check);
      };
      this.listeners.push(check);
      check();
    });
  }

  waitClosed(timeoutMs = 5000): Promise<number> {
    return new Promise((resolve, reject) => {
      if (this.closeCode !== undefined) return resolve(this.closeCode);
      const timer = setTimeout(() => reject(new Error('connection still open')), timeoutMs);
      this.ws.once('close', (code) => {
        clearTimeout(timer);
        resolve(code);
      });
    });
  }

  /** The current value of every point, folded from image, inputs and written messages. */
  values(): Record<string, boolean | number> {
    const out: Record<string, boolean | number> = {};
    for (const m of this.messages) if (m.t === 'image' || m.t === 'inputs' || m.t === 'written') Object.assign(out, m.values);
    return out;
  }

  quality(): Record<string, string> {
    const out: Record<string, string> = {};
    for (const m of this.messages) if (m.t === 'image' || m.t === 'inputs') Object.assign(out, m.quality);
    return out;
  }

  close(): void {
    this.ws.close();
  }
}

/** Polls `check` until it returns true (a state to reach, not a timing assertion). */
export async function eventually(check: () => boolean | Promise<boolean>, timeoutMs = 5000, what = 'condition'): Promise<void> {
  const end = Date.now() + timeoutMs;
  while (Date.now() < end) {
    if (await check()) return;
    await new Promise((r) => setTimeout(r, 20));
  }
  throw new Error(`${what} not reached within ${timeoutMs} ms`);
}

/**
 * A TCP link between the gateway and a device that a test can cut (a pulled cable or a switch that
 * died): while cut, connections are reset and new ones refused; the device behind it keeps its state.
 */
export class CuttableLink {
  private readonly sockets = new Set<Socket>();
  private cut = false;
  private constructor(
    private readonly server: Server,
    readonly port: number,
  ) {}

  static async open(targetPort: number): Promise<CuttableLink> {
    const made: { link?: CuttableLink } = {};
    const server = createNetServer((client) => {
      const link = made.link;
      if (!link || link.cut) {
        client.destroy();
        return;
      }
      const upstream = connect(targetPort, '127.0.0.1');
      for (const [a, b] of [
        [client, upstream],
        [upstream, client],
      ] as const) {
        link.sockets.add(a);
        a.on('error', () => b.destroy());
        a.on('close', () => {
          link.sockets.delete(a);
          b.destroy();
        });
        a.pipe(b);
      }
    });
    const port = await new Promise<number>((resolve) => server.listen(0, '127.0.0.1', () => resolve((server.address() as AddressInfo).port)));
    made.link = new CuttableLink(server, port);
    return made.link;
  }

  /** Resets every connection and refuses new ones until `restore`. */
  sever(): void {
    this.cut = true;
    for (const s of this.sockets) s.destroy();
  }

  restore(): void {
    this.cut = false;
  }

  close(): Promise<void> {
    this.sever();
    return new Promise((resolve) => this.server.close(() => resolve()));
  }
}

/** The real gateway process (`bin/rungsmith-gateway.mjs --no-app`) on a config file, with its URL parsed. */
export interface GatewayProcess {
  readonly proc: ChildProcessWithoutNullStreams;
  readonly port: number;
  readonly token: string;
  /** Everything the process wrote to stderr so far (its log). */
  stderr(): string;
  /** Resolves with the exit code (null when ended by a signal) and the signal. */
  readonly exited: Promise<{ code: number | null; signal: NodeJS.Signals | null }>;
}

export async function spawnGateway(configFile: string): Promise<GatewayProcess> {
  const proc = spawn(process.execPath, ['bin/rungsmith-gateway.mjs', '--port', '0', '--config', configFile, '--no-app'], { stdio: ['pipe', 'pipe', 'pipe'] });
  let log = '';
  proc.stderr.on('data', (d: Buffer) => (log += d.toString()));
  const exited = new Promise<{ code: number | null; signal: NodeJS.Signals | null }>((resolve) => proc.once('exit', (code, signal) => resolve({ code, signal })));
  const line = await new Promise<string>((resolve, reject) => {
    createInterface({ input: proc.stdout }).once('line', resolve);
    proc.once('exit', () => reject(new Error(`gateway exited before printing its URL:\n${log}`)));
  });
  const m = /open http:\/\/127\.0\.0\.1:(\d+)\/#token=(\S+)$/.exec(line);
  if (!m) throw new Error(`unexpected first line: ${line}`);
  return { proc, port: Number(m[1]), token: m[2] ?? '', stderr: () => log, exited };
}

/** When each coil changed on the device, replaying every client's writes in order from all OFF. */
export function coilFlips(writes: readonly LoggedWrite[], count: number, counted: (w: LoggedWrite) => boolean = () => true): number[][] {
  const state = new Array<number>(count).fill(0);
  const flips: number[][] = Array.from({ length: count }, () => []);
  for (const w of writes) {
    if (w.table !== 'co') continue;
    w.values.forEach((v, i) => {
      const coil = w.address + i;
      if (coil >= count || state[coil] === v) return;
      state[coil] = v;
      if (counted(w)) flips[coil]!.push(w.at);
    });
  }
  return flips;
}

/** The most flips of one coil within any window of `ms`. */
export function mostFlipsWithin(flips: readonly number[][], ms: number): number {
  let most = 0;
  for (const times of flips) {
    for (let i = 0; i < times.length; i++) {
      let n = 0;
      for (let j = i; j < times.length && times[j]! - times[i]! < ms; j++) n++;
      most = Math.max(most, n);
    }
  }
  return most;
}
