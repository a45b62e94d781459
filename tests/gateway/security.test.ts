// Security defaults (GATEWAY.md): token, Origin/Host, roles, limits, and hostile input.
import { request } from 'node:http';
import WebSocket from 'ws';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { MAX_CLIENTS, startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { eventually, TestClient } from './helpers';

function upgradeStatus(port: number, headers: Record<string, string>): Promise<number> {
  return new Promise((resolve, reject) => {
    const ws = new WebSocket(`ws://127.0.0.1:${port}/io`, { headers });
    ws.on('unexpected-response', (_req, res) => resolve(res.statusCode ?? 0));
    ws.on('open', () => {
      ws.close();
      resolve(101);
    });
    ws.on('error', (e) => reject(e));
  });
}

function httpStatus(port: number, host: string): Promise<number> {
  return new Promise((resolve, reject) => {
    const req = request({ host: '127.0.0.1', port, path: '/', headers: { Host: host } }, (res) => {
      res.resume();
      resolve(res.statusCode ?? 0);
    });
    req.on('error', reject);
    req.end();
  });
}

describe('gateway security', () => {
  let gw: RunningGateway;
  beforeAll(async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: null } }), distDir: null });
  });
  afterAll(() => gw?.close());

  it('prints a URL with a random 256-bit token in the fragment, never the query', () => {
    expect(gw.url).toMatch(/^http:\/\/127\.0\.0\.1:\d+\/#token=[A-Za-z0-9_-]{43}$/);
  });

  it('refuses a hello without a token, with a wrong token, and a first message that is not hello (1008)', async () => {
    const none = await TestClient.connect(gw.port);
    none.send({ t: 'hello', role: 'controller' });
    expect(await none.waitClosed()).toBe(1008);
    expect(none.messages[0]).toMatchObject({ t: 'error', code: 'not-hello' });

    const wrong = await TestClient.connect(gw.port);
    wrong.send({ t: 'hello', token: gw.token.slice(0, -1) + (gw.token.endsWith('A') ? 'B' : 'A'), role: 'controller' });
    expect(await wrong.waitClosed()).toBe(1008);
    expect(wrong.messages[0]).toMatchObject({ t: 'error', code: 'bad-token' });
    expect(wrong.messages.some((m) => m.t === 'welcome')).toBe(false);

    const early = await TestClient.connect(gw.port);
    early.send({ t: 'outputs', seq: 1, values: { '%QX0.0': true } });
    expect(await early.waitClosed()).toBe(1008);
    expect(gw.simulated?.writtenValues().get('%QX0.0')).toBe(false);
  });

  it('refuses WebSockets from another Origin or through another Host name (DNS rebinding)', async () => {
    expect(await upgradeStatus(gw.port, { Origin: 'http://evil.example' })).toBe(403);
    expect(await upgradeStatus(gw.port, { Origin: `http://127.0.0.1:${gw.port + 1}` })).toBe(403);
    expect(await upgradeStatus(gw.port, { Host: `rebind.example:${gw.port}` })).toBe(403);
    expect(await upgradeStatus(gw.port, { Origin: `http://127.0.0.1:${gw.port}` })).toBe(101);
    expect(await upgradeStatus(gw.port, { Origin: `http://localhost:${gw.port}`, Host: `localhost:${gw.port}` })).toBe(101);
    expect(await httpStatus(gw.port, 'rebind.example')).toBe(403);
  });

  it('gives the lease to one controller: a second controller becomes observer, and observers cannot write', async () => {
    const first = await TestClient.armedController(gw.port, gw.token);
    const second = await TestClient.hello(gw.port, gw.token, 'controller');
    expect(first.messages.find((m) => m.t === 'welcome')).toMatchObject({ role: 'controller' });
    expect(second.messages.find((m) => m.t === 'welcome')).toMatchObject({ role: 'observer' });

    for (const t of ['outputs', 'stop', 'arm'] as const) {
      const before = second.messages.length;
      second.send(t === 'outputs' ? { t, seq: 5, values: { '%QX0.1': true } } : { t, seq: 6 });
      expect(await second.waitFor((m) => m.t === 'error', 3000, before)).toMatchObject({ code: 'not-controller' });
    }
    expect(gw.simulated?.writtenValues().get('%QX0.1')).toBe(false);

    first.send({ t: 'outputs', seq: 1, values: { '%QX0.1': true } });
    await second.waitFor((m) => m.t === 'written' && m.values['%QX0.1'] === true);
    first.close();
    // The controller left: safe state, and the lease is free again.
    await second.waitFor((m) => m.t === 'written' && m.values['%QX0.1'] === false);
    const third = await TestClient.hello(gw.port, gw.token, 'controller');
    expect(third.messages.find((m) => m.t === 'welcome')).toMatchObject({ role: 'controller' });
    second.close();
    third.close();
  });

  it('refuses more than 8 clients that said hello', async () => {
    const clients = [await TestClient.hello(gw.port, gw.token, 'controller')];
    for (let i = 1; i < MAX_CLIENTS; i++) clients.push(await TestClient.hello(gw.port, gw.token, 'observer'));
    await expect(TestClient.connect(gw.port)).rejects.toThrow('HTTP 503');
    clients.forEach((c) => c.close());
    await Promise.all(clients.map((c) => c.waitClosed()));
  });

  it('answers 1,000 malformed or hostile messages with refusals and keeps serving the good client', async () => {
    const good = await TestClient.armedController(gw.port, gw.token);
    const hostile = await TestClient.hello(gw.port, gw.token, 'observer');
    const huge = JSON.stringify({ v: 1, t: 'outputs', seq: 1, values: { '%QX0.0': true }, pad: 'x'.repeat(70 * 1024) });
    const attacks: (string | Buffer)[] = [
      '{not json',
      '',
      'null',
      '[]',
      '42',
      JSON.stringify({ v: 2, t: 'outputs', seq: 1, values: {} }),
      JSON.stringify({ v: 1, t: 'launch-missiles' }),
      JSON.stringify({ v: 1 }),
      JSON.stringify({ v: 1, t: 'outputs', seq: 'one', values: {} }),
      JSON.stringify({ v: 1, t: 'outputs', seq: -1, values: {} }),
      JSON.stringify({ v: 1, t: 'outputs', seq: 1, values: { '%QX0.0': 'TRUE' } }),
      JSON.stringify({ v: 1, t: 'outputs', seq: 1, values: { '%QX99.0': true } }),
      JSON.stringify({ v: 1, t: 'simulate', seq: 1, values: { '%QX0.0': true } }),
      JSON.stringify({ v: 1, t: 'simulate', seq: 1, values: { '%IX42.0': true } }),
      JSON.stringify({ v: 1, t: 'simulate', seq: 1, values: { '%IW0': 70000 } }),
      JSON.stringify({ v: 1, t: 'simulate', seq: 1, values: { '%IX0.0': 1 } }),
      '{"v":1,"t":"simulate","seq":1,"values":{"__proto__":true}}',
      JSON.stringify({ v: 1, t: 'hello', token: gw.token, role: 'controller' }),
      JSON.stringify({ v: 1, t: 'resync', extra: 'field' }),
      huge,
      Buffer.from([0xde, 0xad, 0xbe, 0xef]),
    ];
    // Four hostile connections at ~150 msgs/s each: below the flood limit, so every message gets its own refusal.
    const extra = await Promise.all([0, 1, 2].map(() => TestClient.hello(gw.port, gw.token, 'observer')));
    const senders = [hostile, ...extra];
    const perSender = 250;
    let scan = 0;
    const goodLoop = setInterval(() => {
      scan++;
      good.send({ t: 'outputs', seq: scan, values: { '%QX0.2': scan % 2 === 0 } });
    }, 20);
    try {
      await Promise.all(
        senders.map(async (s) => {
          for (let i = 0; i < perSender; i++) {
            const a = attacks[i % attacks.length] ?? '';
            if (Buffer.isBuffer(a)) s.ws.send(a, { binary: true });
            else s.sendRaw(a);
            if (i % 15 === 14) await new Promise((r) => setTimeout(r, 100));
          }
        }),
      );
      for (const s of senders) await eventually(() => s.messages.filter((m) => m.t === 'error').length >= perSender, 5000, 'all refused');
      // The good client is still served: its outputs reach the device and it can resync.
      const before = good.messages.length;
      good.send({ t: 'resync' });
      await good.waitFor((m) => m.t === 'image', 3000, before);
    } finally {
      clearInterval(goodLoop);
    }
    for (const s of senders) {
      const errors = s.messages.filter((m) => m.t === 'error');
      expect(errors).toHaveLength(perSender);
      expect(s.closeCode).toBeUndefined();
      expect(new Set(errors.map((e) => e.t === 'error' && e.code))).toEqual(
        new Set(['bad-json', 'bad-message', 'not-controller', 'not-input', 'bad-value', 'unknown-address', 'already-hello', 'too-large']),
      );
    }
    expect(good.messages.filter((m) => m.t === 'error')).toEqual([]);
    expect(good.closeCode).toBeUndefined();
    await eventually(() => gw.simulated?.writtenValues().get('%QX0.2') === (scan % 2 === 0), 3000, 'good outputs applied');
    good.send({ t: 'stop' });
    [good, ...senders].forEach((c) => c.close());
  });

  it('survives a frame far beyond the limit: that connection is closed (1009), the gateway keeps serving', async () => {
    const good = await TestClient.hello(gw.port, gw.token, 'observer');
    const bad = await TestClient.hello(gw.port, gw.token, 'observer');
    bad.sendRaw('x'.repeat(2 * 1024 * 1024));
    expect(await bad.waitClosed()).toBe(1009);
    const before = good.messages.length;
    good.send({ t: 'resync' });
    await good.waitFor((m) => m.t === 'image', 3000, before);
    good.close();
  });

  it('closes a flooding client with 1008 and keeps serving the others', async () => {
    const good = await TestClient.hello(gw.port, gw.token, 'observer');
    const flood = await TestClient.hello(gw.port, gw.token, 'observer');
    for (let i = 0; i < 600; i++) flood.send({ t: 'resync' });
    expect(await flood.waitClosed()).toBe(1008);
    expect(flood.messages.some((m) => m.t === 'error' && m.code === 'flood')).toBe(true);
    const before = good.messages.length;
    good.send({ t: 'resync' });
    await good.waitFor((m) => m.t === 'image', 3000, before);
    good.close();
  });
});
