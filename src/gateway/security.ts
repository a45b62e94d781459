// Token, Origin/Host allow-lists, the per-client message budget and the handshake rate (GATEWAY.md security defaults).
import { createHash, randomBytes, timingSafeEqual } from 'node:crypto';

/** A random 256-bit token, URL-safe. */
export const newToken = () => randomBytes(32).toString('base64url');

/** Constant-time comparison; hashing first makes the lengths equal so the length leaks nothing either. */
export function tokenMatches(expected: string, given: string): boolean {
  const a = createHash('sha256').update(expected).digest();
  const b = createHash('sha256').update(given).digest();
  return timingSafeEqual(a, b);
}

/** Hosts a browser may use to reach us on `port` (anything else is DNS rebinding). */
export function defaultHosts(port: number): string[] {
  return [`127.0.0.1:${port}`, `localhost:${port}`, `[::1]:${port}`];
}

/** Same origin by default: the page the gateway itself serves. */
export function defaultOrigins(port: number): string[] {
  return defaultHosts(port).map((h) => `http://${h}`);
}

export function hostAllowed(host: string | undefined, allowed: ReadonlySet<string>): boolean {
  return host !== undefined && allowed.has(host.toLowerCase());
}

/** Browsers always send Origin on WebSocket requests; a missing one is a non-browser client, which still needs the token. */
export function originAllowed(origin: string | undefined, allowed: ReadonlySet<string>): boolean {
  return origin === undefined || allowed.has(origin.toLowerCase().replace(/\/$/, ''));
}

/** Token bucket: `rate` per second on average, bursts up to `burst` (default `rate`). */
export class RateLimiter {
  private tokens: number;
  private last: number;
  constructor(
    private readonly rate: number,
    private readonly burst = rate,
    now = Date.now(),
  ) {
    this.tokens = burst;
    this.last = now;
  }
  /** Tokens available at `now` (refilled since the last call). */
  level(now = Date.now()): number {
    this.tokens = Math.min(this.burst, this.tokens + (Math.max(0, now - this.last) / 1000) * this.rate);
    this.last = Math.max(this.last, now);
    return this.tokens;
  }
  /** True when the bucket is full again, i.e. it remembers nothing a new bucket would not. */
  full(now = Date.now()): boolean {
    return this.level(now) >= this.burst;
  }
  take(now = Date.now()): boolean {
    if (this.level(now) < 1) return false;
    this.tokens -= 1;
    return true;
  }
  /**
   * Like `take`, but the bucket may hold `creditMs` worth of extra tokens: the messages a client sent
   * while this process could not read them (an event-loop stall) arrive together afterwards, and were
   * sent at the client's own rate, not as a burst (see StallMeter).
   */
  takeWithCredit(creditMs: number, now = Date.now()): boolean {
    if (creditMs <= 0) return this.take(now);
    const cap = this.burst + (creditMs / 1000) * this.rate;
    this.tokens = Math.min(cap, this.tokens + (Math.max(0, now - this.last) / 1000) * this.rate);
    this.last = Math.max(this.last, now);
    if (this.tokens < 1) return false;
    this.tokens -= 1;
    return true;
  }
}

/**
 * Event-loop stalls of this process: while the gateway is busy (a huge image, a slow disk, the OS
 * starving it) a client's messages queue in the socket and are all read at once when it resumes.
 * A tick every TICK_MS notes the time; a message read long after the last tick, or soon after a
 * tick that came late, arrived behind a stall of that length. The message budget grants that time
 * as credit, so a backlog is not mistaken for a flood; a client that really sends too fast is still
 * closed (its rate exceeds the budget outside the stall too).
 */
export class StallMeter {
  static readonly TICK_MS = 20;
  /** How long after a stall its backlog may still be being read. */
  static readonly BACKLOG_WINDOW_MS = 1000;
  private lastTick = Date.now();
  private stall = { ms: 0, endedAt: 0 };
  private readonly timer: NodeJS.Timeout;
  constructor() {
    this.timer = setInterval(() => this.tick(), StallMeter.TICK_MS);
    this.timer.unref();
  }
  private tick(now = Date.now()): void {
    const late = now - this.lastTick - StallMeter.TICK_MS;
    if (late > 2 * StallMeter.TICK_MS) this.stall = { ms: late, endedAt: now };
    this.lastTick = now;
  }
  /** The length of the stall a message read at `now` may have waited behind (0 when none). */
  creditMs(now = Date.now()): number {
    const ongoing = now - this.lastTick - StallMeter.TICK_MS;
    const recent = now - this.stall.endedAt <= StallMeter.BACKLOG_WINDOW_MS ? this.stall.ms : 0;
    return Math.max(0, recent, ongoing > 2 * StallMeter.TICK_MS ? ongoing : 0);
  }
  stop(): void {
    clearInterval(this.timer);
  }
}

/** WebSocket handshakes a remote IP may make at once, then per second (reconnects included). */
export const HANDSHAKE_BURST = 32;
export const HANDSHAKES_PER_SECOND = 8;

/** Buckets beyond this many are pruned of full ones (which carry no state). */
const MAX_TRACKED = 1024;

function prune(map: Map<string, RateLimiter>, now: number): void {
  if (map.size < MAX_TRACKED) return;
  for (const [k, b] of map) if (b.full(now)) map.delete(k);
  // Still too many (a spray of identities): forget the oldest; the per-IP handshake budget bounds this.
  for (const k of map.keys()) {
    if (map.size < MAX_TRACKED) break;
    map.delete(k);
  }
}

/**
 * WebSocket handshakes per remote IP address (a reconnect loop keeps its IP, not its port): `burst` at
 * once, then `rate` per second. Excess handshakes are refused with HTTP 429 before any WebSocket work.
 */
export class HandshakeLimiter {
  private readonly buckets = new Map<string, RateLimiter>();
  constructor(
    private readonly rate: number,
    private readonly burst: number,
  ) {}
  allow(ip: string, now = Date.now()): boolean {
    let bucket = this.buckets.get(ip);
    if (!bucket) {
      prune(this.buckets, now);
      bucket = new RateLimiter(this.rate, this.burst, now);
      this.buckets.set(ip, bucket);
    }
    return bucket.take(now);
  }
}

/**
 * The per-connection message budget, carried across reconnects of one client identity (remote IP,
 * Origin and User-Agent): a closed connection leaves its bucket here, and the identity's next
 * connection continues from it instead of a full one, until it has refilled anyway. Connections open
 * at the same time each have their own bucket; when they close, the emptier one is kept.
 */
export class MessageBudgets {
  private readonly parked = new Map<string, RateLimiter>();
  constructor(private readonly rate: number) {}

  /** The bucket for a new connection of `identity`. */
  take(identity: string, now = Date.now()): RateLimiter {
    const parked = this.parked.get(identity);
    this.parked.delete(identity);
    return parked && !parked.full(now) ? parked : new RateLimiter(this.rate, this.rate, now);
  }

  /** A connection of `identity` closed with `bucket`. */
  park(identity: string, bucket: RateLimiter, now = Date.now()): void {
    if (bucket.full(now)) return;
    const other = this.parked.get(identity);
    if (other && other.level(now) <= bucket.level(now)) return;
    prune(this.parked, now);
    this.parked.set(identity, bucket);
  }
}

/** Who a connection is across reconnects: its remote IP, and the Origin and User-Agent it sent. */
export function clientIdentity(ip: string | undefined, origin: string | undefined, userAgent: string | undefined): string {
  return JSON.stringify([ip ?? '', origin ?? '', userAgent ?? '']);
}
