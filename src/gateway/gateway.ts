// Composes the gateway: devices, I/O hub, HTTP (the app) and the WebSocket endpoint /io on 127.0.0.1.
import { randomUUID } from 'node:crypto';
import { createServer, type IncomingMessage, type Server } from 'node:http';
import type { AddressInfo, Socket } from 'node:net';
import { resolve } from 'node:path';
import { WebSocketServer } from 'ws';
import { IO_PATH, MAX_FRAME_BYTES, PROTOCOL_VERSION, type GatewayMessageBody } from '../protocol/messages';
import type { Quality, WireValue } from '../protocol/points';
import { resolveConfig, type ResolvedConfig } from './config';
import type { Device, Values } from './device';
import { IoHub, type ShutdownReport } from './ioHub';
import { ModbusTcpDevice } from './modbusDevice';
import {
  clientIdentity,
  defaultHosts,
  defaultOrigins,
  HANDSHAKE_BURST,
  HANDSHAKES_PER_SECOND,
  HandshakeLimiter,
  hostAllowed,
  MessageBudgets,
  newToken,
  originAllowed,
  StallMeter,
} from './security';
import { MESSAGES_PER_SECOND, Session } from './session';
import { SimulatedDevice } from './simulatedDevice';
import { serveStatic, setSecurityHeaders } from './staticFiles';

/** Sessions that said hello (observers and the controller); the last one is kept for a controller. */
export const MAX_CLIENTS = 8;
/**
 * Sockets still waiting for their hello. They do not take the slots above; when this many wait, the
 * one that waited longest is closed for a new one, so silent sockets can never lock a controller out.
 */
export const MAX_WAITING_FOR_HELLO = 16;
/** The simulated device writes at once; a controller need not send it outputs more often than this. */
const SIMULATED_POLL_MS = 50;
/** The cached image frame is rebuilt at least this often even when no change was reported. */
const IMAGE_CACHE_MS = 1000;
/** Frames between 64 KiB and this get an error reply; beyond it `ws` closes the connection (1009). */
const HARD_FRAME_LIMIT = 16 * MAX_FRAME_BYTES;

export interface GatewayOptions {
  /** TCP port on 127.0.0.1; 0 picks a free one. */
  readonly port: number;
  readonly config?: ResolvedConfig;
  /** Directory of the built app to serve, or null to serve only /io. */
  readonly distDir?: string | null;
  /** Fixed token; otherwise config.token, else a random 256-bit one. */
  readonly token?: string;
  readonly log?: (line: string) => void;
}

export interface RunningGateway {
  readonly port: number;
  readonly token: string;
  /** The URL to open: http://127.0.0.1:PORT/#token=… */
  readonly url: string;
  readonly hub: IoHub;
  readonly simulated: SimulatedDevice | undefined;
  /**
   * Stops dispatching messages, writes the safe state as the last write on every device, then
   * closes everything. Reports whether every device acknowledged the safe state.
   */
  close(): Promise<ShutdownReport>;
}

export async function startGateway(opts: GatewayOptions): Promise<RunningGateway> {
  const config = opts.config ?? resolveConfig({});
  const log = opts.log ?? (() => undefined);
  const token = opts.token ?? config.token ?? newToken();
  const simulated = config.devices.length === 0 ? new SimulatedDevice(config.simulated.modbusPort, config.simulated.plant, log, config.simulated.masterWatchdogMs) : undefined;
  const devices: Device[] = simulated ? [simulated] : config.devices.map((d) => new ModbusTcpDevice(d));

  const pollMs = simulated ? SIMULATED_POLL_MS : Math.min(...config.devices.map((d) => d.pollMs));
  const sessions = new Set<Session>();
  let seq = 0;
  const broadcast = (body: GatewayMessageBody) => {
    for (const s of sessions) if (s.role) s.send(body);
  };
  const toRecord = (m: Values) => Object.fromEntries(m) as Record<string, WireValue>;
  // The full image, serialised once and reused for every welcome and resync until something changes
  // (a large map has thousands of points: building it per request would starve the event loop).
  let imageCache: { readonly body: string; readonly at: number } | undefined;
  const imageFrame = (frameSeq: number): string => {
    const now = Date.now();
    if (!imageCache || now - imageCache.at > IMAGE_CACHE_MS) {
      const { values, quality } = hub.image();
      imageCache = { body: `"values":${JSON.stringify(values)},"quality":${JSON.stringify(quality)}`, at: now };
    }
    return `{"v":${PROTOCOL_VERSION},"t":"image","seq":${frameSeq},${imageCache.body}}`;
  };
  const hub = new IoHub(devices, { watchdogMs: config.watchdogMs, autoRearm: config.autoRearm }, {
    inputs: (values, quality: ReadonlyMap<string, Quality>) => {
      imageCache = undefined;
      broadcast({ t: 'inputs', seq: ++seq, values: toRecord(values), quality: Object.fromEntries(quality) });
    },
    written: (values) => {
      imageCache = undefined;
      broadcast({ t: 'written', seq: ++seq, values: toRecord(values) });
    },
    status: () => {
      imageCache = undefined;
      broadcast({ t: 'status', ...hub.status() });
    },
    log,
  });
  await hub.start();

  const distDir = opts.distDir === undefined || opts.distDir === null ? null : resolve(opts.distDir);
  let allowedHosts = new Set<string>();
  let allowedOrigins = new Set<string>();
  const server: Server = createServer((req, res) => {
    if (!hostAllowed(req.headers.host, allowedHosts)) {
      setSecurityHeaders(req, res);
      res.writeHead(403, { 'Content-Type': 'text/plain' }).end('Host not allowed\n');
      return;
    }
    serveStatic(distDir, req, res);
  });
  const wss = new WebSocketServer({ noServer: true, maxPayload: HARD_FRAME_LIMIT, perMessageDeflate: false });
  wss.on('error', () => undefined);

  const reject = (socket: Socket, status: number, text: string, extra = '') => {
    socket.end(`HTTP/1.1 ${status} ${text}\r\nConnection: close\r\n${extra}Content-Type: text/plain\r\nContent-Length: ${text.length + 1}\r\n\r\n${text}\n`);
  };
  // Connection budget (GATEWAY.md security defaults): handshakes per remote IP, the message budget
  // carried across a client's reconnects, and the last of MAX_CLIENTS connections kept for a controller.
  const handshakes = new HandshakeLimiter(HANDSHAKES_PER_SECOND, HANDSHAKE_BURST);
  const budgets = new MessageBudgets(MESSAGES_PER_SECOND);
  const stalls = new StallMeter();
  const live = () => [...sessions].filter((s) => !s.isClosed);
  const mayObserve = () => live().filter((s) => s.role === 'observer').length < MAX_CLIENTS - 1;
  /** Handshakes accepted whose session does not exist yet. */
  let upgrading = 0;
  let accepting = true;
  server.on('upgrade', (req: IncomingMessage, socket: Socket, head: Buffer) => {
    socket.on('error', () => socket.destroy());
    if (!accepting) return reject(socket, 503, 'Service Unavailable');
    const path = (req.url ?? '').split('?')[0];
    if (path !== IO_PATH) return reject(socket, 404, 'Not Found');
    if (!handshakes.allow(socket.remoteAddress ?? '')) return reject(socket, 429, 'Too Many Requests', 'Retry-After: 1\r\n');
    if (!hostAllowed(req.headers.host, allowedHosts)) return reject(socket, 403, 'Forbidden');
    if (!originAllowed(req.headers.origin, allowedOrigins)) {
      log(`refused WebSocket from origin ${req.headers.origin}`);
      return reject(socket, 403, 'Forbidden');
    }
    // Slots are taken by hello: only welcomed sessions count against MAX_CLIENTS. Sockets waiting for
    // their hello are bounded apart, the longest-waiting one giving way to a new one.
    const open = live();
    if (open.filter((s) => s.role !== null).length >= MAX_CLIENTS) return reject(socket, 503, 'Service Unavailable');
    const waiting = open.filter((s) => s.role === null);
    for (let i = 0; i <= waiting.length + upgrading - MAX_WAITING_FOR_HELLO && i < waiting.length; i++) waiting[i]?.evict();
    upgrading++;
    const identity = clientIdentity(socket.remoteAddress, req.headers.origin, req.headers['user-agent']);
    let settled = false;
    const settle = () => {
      if (!settled) upgrading--;
      settled = true;
    };
    socket.once('close', settle);
    wss.handleUpgrade(req, socket, head, (ws) => {
      settle();
      const limiter = budgets.take(identity);
      const session = new Session(randomUUID().slice(0, 8), ws, { hub, token, simulated, nextSeq: () => ++seq, log, limiter, mayObserve, stalls, imageFrame, pollMs });
      sessions.add(session);
      ws.on('close', () => {
        sessions.delete(session);
        budgets.park(identity, limiter);
      });
    });
  });
  server.on('clientError', (_err, socket) => socket.destroy());

  await new Promise<void>((ok, fail) => {
    server.once('error', (e: NodeJS.ErrnoException) => {
      void hub.shutdown();
      fail(e.code === 'EADDRINUSE' ? new Error(`port ${opts.port} on 127.0.0.1 is in use; choose another with --port N or PORT`) : e);
    });
    server.listen(opts.port, '127.0.0.1', () => {
      server.removeAllListeners('error');
      ok();
    });
  });
  server.on('error', (e) => log(`HTTP server error: ${e.message}`));
  const port = (server.address() as AddressInfo).port;
  allowedHosts = new Set([...defaultHosts(port), ...config.allowedHosts].map((h) => h.toLowerCase()));
  allowedOrigins = new Set([...defaultOrigins(port), ...config.allowedOrigins].map((o) => o.toLowerCase().replace(/\/$/, '')));

  let closing: Promise<ShutdownReport> | undefined;
  const close = () =>
    (closing ??= (async () => {
      // 1. Nothing more is dispatched or accepted: no `outputs` can follow the safe write.
      accepting = false;
      stalls.stop();
      for (const s of sessions) s.silence();
      // 2. The safe image as the last write on every device.
      const report = await hub.shutdown();
      // 3. Then the connections.
      for (const c of wss.clients) c.close(1001, 'gateway shutting down');
      wss.close();
      server.closeAllConnections();
      await new Promise<void>((ok) => server.close(() => ok()));
      return report;
    })());

  return { port, token, url: `http://127.0.0.1:${port}/#token=${token}`, hub, simulated, close };
}
