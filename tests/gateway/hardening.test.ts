// Connection budget (GATEWAY.md security defaults): silent sockets, the slot kept for a controller,
// reconnect loops and the message budget carried across reconnects.
import WebSocket from 'ws';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { MAX_CLIENTS, startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { HANDSHAKE_BURST, HandshakeLimiter, MessageBudgets, RateLimiter } from '../../src/gateway/security';
import { MESSAGES_PER_SECOND } from '../../src/gateway/session';
import { eventually, TestClient } from './helpers';

/** Opens /io, says hello as `role` and closes at once; resolves with the HTTP status of the handshake (101 when accepted). */
function helloAndLeave(port: number, token: string, headers: Record<string, string> = {}): Promise<{ status: number; retryAfter?: string }> {
  return new Promise((resolve, reject) => {
    const ws = new WebSocket(`ws://127.0.0.1:${port}/io`, { headers });
    ws.on('unexpected-response', (_req, res) => {
      res.resume();
      resolve({ status: res.statusCode ?? 0, retryAfter: res.headers['retry-after'] });
    });
    ws.on('open', () => {
      ws.send(JSON.stringify({ v: 1, t: 'hello', token, role: 'observer' }));
      ws.close();
      resolve({ status: 101 });
    });
    ws.on('error', (e) => {
      if (!/Unexpected server response/.test(e.message)) reject(e);
    });
  });
}

/** Retries a controller hello while the gateway answers 503 (all connections taken) or 1013 (the old controller's close is still being handled). */
async function controllerGetsIn(port: number, token: string, timeoutMs = 10_000): Promise<TestClient> {
  const end = Date.now() + timeoutMs;
  for (;;) {
    try {
      return await TestClient.hello(port, token, 'controller');
    } catch (e) {
      if (!/HTTP 503|\(1013\)/.test(String(e)) || Date.now() > end) throw e;
      await new Promise((r) => setTimeout(r, 100));
    }
  }
}

describe('gateway connection budget', () => {
  let gw: RunningGateway;
  const clients: TestClient[] = [];
  beforeEach(async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: null } }), distDir: null });
  });
  afterEach(async () => {
    for (const c of clients.splice(0)) c.close();
    await gw?.close();
  });

  it(`closes sockets that never say hello, so ${MAX_CLIENTS} silent sockets do not lock out a controller`, async () => {
    const silent = await Promise.all(Array.from({ length: MAX_CLIENTS }, () => TestClient.connect(gw.port)));
    clients.push(...silent);
    const controller = await controllerGetsIn(gw.port, gw.token);
    clients.push(controller);
    expect(controller.messages.find((m) => m.t === 'welcome')).toMatchObject({ role: 'controller' });
    for (const s of silent) {
      expect(await s.waitClosed()).toBe(1008);
      expect(s.messages[0]).toMatchObject({ t: 'error', code: 'not-hello', message: 'no hello within 1.5 s' });
    }
    // The controller that got in drives the outputs.
    controller.send({ t: 'arm' });
    controller.send({ t: 'outputs', seq: 1, values: { '%QX0.4': true } });
    await controller.waitFor((m) => m.t === 'written' && m.values['%QX0.4'] === true);
  });

  it('keeps the last connection for a controller: observers may not take it, a controller that reconnects gets it', async () => {
    const observers = [];
    for (let i = 0; i < MAX_CLIENTS - 1; i++) observers.push(await TestClient.hello(gw.port, gw.token, 'observer'));
    clients.push(...observers);
    expect(observers.every((o) => o.messages.some((m) => m.t === 'welcome' && m.role === 'observer'))).toBe(true);

    // One more observer is refused with "try again later" (1013), not a policy close: a browser retries.
    const extra = await TestClient.connect(gw.port);
    clients.push(extra);
    extra.send({ t: 'hello', token: gw.token, role: 'observer' });
    expect(await extra.waitClosed()).toBe(1013);
    expect(extra.messages.some((m) => m.t === 'welcome')).toBe(false);
    expect(extra.messages[0]).toMatchObject({ t: 'error', code: 'not-controller' });

    // A controller gets the last connection, and then the gateway is full.
    const controller = await controllerGetsIn(gw.port, gw.token);
    clients.push(controller);
    expect(controller.messages.find((m) => m.t === 'welcome')).toMatchObject({ role: 'controller' });
    await expect(TestClient.connect(gw.port)).rejects.toThrow('HTTP 503');

    // The controller's connection drops; it reconnects and is controller again, the observers stay.
    controller.close();
    await controller.waitClosed();
    const again = await controllerGetsIn(gw.port, gw.token);
    clients.push(again);
    expect(again.messages.find((m) => m.t === 'welcome')).toMatchObject({ role: 'controller' });
    expect(observers.every((o) => o.closeCode === undefined)).toBe(true);

    // An observer that leaves frees its place for another observer; then all connections are in use.
    const leaving = observers.pop();
    leaving?.close();
    await leaving?.waitClosed();
    let replacement: TestClient | undefined;
    const tryObserver = async () => {
      try {
        replacement = await TestClient.hello(gw.port, gw.token, 'observer');
        clients.push(replacement);
        return true;
      } catch {
        return false; // the leaving observer's close is still being handled
      }
    };
    await eventually(tryObserver, 5000, 'another observer admitted');
    expect(replacement?.messages.find((m) => m.t === 'welcome')).toMatchObject({ role: 'observer' });
    await expect(TestClient.connect(gw.port)).rejects.toThrow('HTTP 503');
  });

  it('answers a client reconnecting in a tight loop with 429, and keeps answering the controller already connected', async () => {
    const good = await TestClient.hello(gw.port, gw.token, 'controller');
    clients.push(good);
    good.send({ t: 'arm' });
    let scan = 0;
    let resyncs = 0;
    const imagesBefore = good.messages.filter((m) => m.t === 'image').length;
    const goodLoop = setInterval(() => {
      scan++;
      good.send({ t: 'outputs', seq: scan, values: { '%QX0.2': scan % 2 === 0 } });
      if (scan % 50 === 0) {
        resyncs++;
        good.send({ t: 'resync' });
      }
    }, 10);
    const statuses: { status: number; retryAfter?: string }[] = [];
    try {
      // Four reconnect loops from the same address, each reconnecting as soon as the last attempt ended.
      await Promise.all(
        [0, 1, 2, 3].map(async () => {
          for (let i = 0; i < 100; i++) statuses.push(await helloAndLeave(gw.port, gw.token));
        }),
      );
      await eventually(() => good.messages.filter((m) => m.t === 'image').length - imagesBefore >= resyncs, 5000, 'every resync answered');
    } finally {
      clearInterval(goodLoop);
    }
    const refused = statuses.filter((s) => s.status === 429);
    expect(refused.length).toBeGreaterThan(0);
    expect(refused.every((s) => s.retryAfter === '1')).toBe(true);
    expect(statuses.filter((s) => s.status === 101).length).toBeLessThan(statuses.length - HANDSHAKE_BURST);
    // The controller was answered throughout: no refusals, still connected, its last outputs applied.
    expect(good.messages.filter((m) => m.t === 'error')).toEqual([]);
    expect(good.closeCode).toBeUndefined();
    await eventually(() => gw.simulated?.writtenValues().get('%QX0.2') === (scan % 2 === 0), 3000, 'good outputs applied');
    good.send({ t: 'stop' });
  });

  it('carries the message budget over to the next connection of the same client instead of a fresh one', async () => {
    const ua = { 'User-Agent': 'flooder/1.0' };
    const connect = async (headers: Record<string, string>) => {
      const c = await TestClient.connect(gw.port, headers);
      clients.push(c);
      c.send({ t: 'hello', token: gw.token, role: 'observer' });
      await c.waitFor((m) => m.t === 'status');
      return c;
    };
    const first = await connect(ua);
    // `arm` from an observer: a cheap message that is always answered (refused: not the controller).
    for (let i = 0; i < 3 * MESSAGES_PER_SECOND; i++) first.send({ t: 'arm' });
    expect(await first.waitClosed()).toBe(1008);
    expect(first.messages.some((m) => m.t === 'error' && m.code === 'flood')).toBe(true);

    // Reconnecting does not buy a fresh budget: far fewer messages than the limit close it again.
    const burst = Math.round(MESSAGES_PER_SECOND * 0.9);
    const second = await TestClient.connect(gw.port, ua);
    clients.push(second);
    second.send({ t: 'hello', token: gw.token, role: 'observer' });
    for (let i = 0; i < burst; i++) second.send({ t: 'arm' });
    expect(await second.waitClosed()).toBe(1008);
    expect(second.messages.some((m) => m.t === 'error' && m.code === 'flood')).toBe(true);

    // Another client (another User-Agent) has its own budget: the same burst is answered in full.
    const other = await connect({ 'User-Agent': 'observer/2.0' });
    const before = other.messages.length;
    for (let i = 0; i < burst; i++) other.send({ t: 'arm' });
    const answered = () => other.messages.slice(before).filter((m) => m.t === 'error' && m.code === 'not-controller').length;
    await eventually(() => answered() === burst, 5000, 'every message answered');
    expect(other.closeCode).toBeUndefined();
  });
});

describe('connection budget bookkeeping', () => {
  it('gives a remote address a burst of handshakes, then a steady rate, per address', () => {
    const limiter = new HandshakeLimiter(8, 32);
    const t0 = 1_000_000;
    const first = Array.from({ length: 40 }, () => limiter.allow('127.0.0.1', t0));
    expect(first.filter(Boolean)).toHaveLength(32);
    expect(limiter.allow('127.0.0.2', t0)).toBe(true);
    expect(limiter.allow('127.0.0.1', t0 + 100)).toBe(false);
    const later = Array.from({ length: 20 }, () => limiter.allow('127.0.0.1', t0 + 1000));
    expect(later.filter(Boolean)).toHaveLength(8);
  });

  it('lets the messages that queued during a stall of the gateway through, and still stops a client that really floods', () => {
    const t0 = 7_000_000;
    // 150 messages/s for 3 s while the gateway could not read: 450 arrive at once when it resumes.
    const stalled = new RateLimiter(200, 200, t0);
    const afterStall = t0 + 3000;
    expect(Array.from({ length: 450 }, () => stalled.takeWithCredit(3000, afterStall)).every(Boolean)).toBe(true);
    // Without the stall as credit the same backlog is cut at the burst.
    const plain = new RateLimiter(200, 200, t0);
    expect(Array.from({ length: 450 }, () => plain.take(afterStall)).filter(Boolean)).toHaveLength(200);
    // The credit is the stall's length, not more: 1,000 at once after a 3 s stall is a flood.
    const flooder = new RateLimiter(200, 200, t0);
    expect(Array.from({ length: 1000 }, () => flooder.takeWithCredit(3000, afterStall)).filter(Boolean).length).toBeLessThan(1000);
  });

  it('resumes a reconnecting client from the budget its last connection left, until it has refilled', () => {
    const budgets = new MessageBudgets(200);
    const t0 = 5_000_000;
    const a = budgets.take('client', t0);
    for (let i = 0; i < 150; i++) expect(a.take(t0)).toBe(true);
    budgets.park('client', a, t0);
    const b = budgets.take('client', t0);
    expect(Array.from({ length: 100 }, () => b.take(t0)).filter(Boolean)).toHaveLength(50);
    expect(budgets.take('someone else', t0).level(t0)).toBe(200);
    budgets.park('client', b, t0);
    // One second later the budget has refilled: the next connection starts full.
    expect(budgets.take('client', t0 + 1000).level(t0 + 1000)).toBe(200);
  });
});
