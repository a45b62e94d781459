// The Modbus supervisor against peers that misbehave at the TCP level.
import { createServer, type Server, type Socket } from 'node:net';
import { afterEach, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { TestClient } from './helpers';

const deviceAt = (port: number) =>
  resolveConfig({
    devices: [{ id: 'io', host: '127.0.0.1', port, pollMs: 50, timeoutMs: 150, points: [{ address: '%IX0.0', count: 8 }, { address: '%QX0.0' }] }],
  });

describe('Modbus TCP supervisor', () => {
  let gw: RunningGateway | undefined;
  let silent: Server | undefined;
  const sockets: Socket[] = [];
  afterEach(async () => {
    await gw?.close();
    sockets.forEach((s) => s.destroy());
    await new Promise<void>((r) => (silent ? silent.close(() => r()) : r()));
  });

  it('times out a peer that accepts the connection but never answers, and reports it offline with stale inputs', async () => {
    silent = createServer((s) => {
      sockets.push(s);
      s.on('error', () => undefined);
    });
    const port = await new Promise<number>((r) => silent!.listen(0, '127.0.0.1', () => r((silent!.address() as { port: number }).port)));
    gw = await startGateway({ port: 0, config: deviceAt(port), distDir: null });
    const c = await TestClient.hello(gw.port, gw.token, 'observer');
    const offline = await c.waitFor((m) => m.t === 'status' && m.devices[0]?.state === 'offline', 5000);
    expect(offline.t === 'status' && offline.devices[0]?.error).toMatch(/timed out/i);
    expect(c.quality()['%IX0.0']).toBe('stale');
    expect(sockets.length).toBeGreaterThanOrEqual(1);
    c.close();
  });

  it('reports a device nobody listens for as offline with the connection error', async () => {
    gw = await startGateway({ port: 0, config: deviceAt(await freeLoopbackPort()), distDir: null });
    const c = await TestClient.hello(gw.port, gw.token, 'observer');
    const offline = await c.waitFor((m) => m.t === 'status' && m.devices[0]?.state === 'offline', 5000);
    expect(offline.t === 'status' && offline.devices[0]?.error).toMatch(/ECONNREFUSED/);
    // An offline device cannot be armed (it could come back restarted); outputs are refused.
    const ctl = await TestClient.hello(gw.port, gw.token, 'controller');
    ctl.send({ t: 'arm', seq: 1 });
    const refused = await ctl.waitFor((m) => m.t === 'error', 5000);
    expect(refused).toMatchObject({ code: 'arm-refused', ref: 1 });
    expect(refused.t === 'error' && refused.message).toMatch(/device "io" is offline/);
    ctl.send({ t: 'outputs', seq: 2, values: { '%QX0.0': true } });
    expect(await ctl.waitFor((m) => m.t === 'error' && m.ref === 2, 5000)).toMatchObject({ code: 'disarmed' });
    expect(ctl.lastStatus()).toMatchObject({ armed: false, disarm: { cause: 'start' }, devices: [{ outputs: 'safe-pending' }] });
    c.close();
    ctl.close();
  });
});
