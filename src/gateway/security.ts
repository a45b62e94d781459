// Token, Origin/Host allow-lists and the per-client rate limit (GATEWAY.md security defaults).
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

/** Token bucket: `rate` messages per second on average, bursts up to `rate`. */
export class RateLimiter {
  private tokens: number;
  private last = Date.now();
  constructor(private readonly rate: number) {
    this.tokens = rate;
  }
  take(now = Date.now()): boolean {
    this.tokens = Math.min(this.rate, this.tokens + ((now - this.last) / 1000) * this.rate);
    this.last = now;
    if (this.tokens < 1) return false;
    this.tokens -= 1;
    return true;
  }
}
