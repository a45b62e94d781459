// A connection reset (TCP RST) while a write is on the wire: the CI run of 2026-11-28 left a device
// unconfirmed at shutdown after its restart. modbus-serial marks the port closed on the socket's
// error and then swallows the 'close' event, so a request in flight on a reset connection was only
// settled by its own timeout — for the safe write, up to safeWriteTimeoutMs (10 s), longer than the
// shutdown deadline (4 s). Here a proxy in front of pymodbus swallows the safe write of a disarm and
// then resets the connection (as a device that restarts does), and the gateway shuts down at once:
// it must notice the reset, reconnect, and have the device acknowledge the safe image before it exits.
import { createServer, connect, type Server, type Socket } from 'node:net';
import { afterEach, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { eventually, PyModbusServer, TestClient } from './helpers';

/** Forwards Modbus TCP to the device; `swallow` drops what the gateway sends (nothing answers) until `reset`. */
class Proxy {
  swallow = false;
  swallowed = 0;
  private readonly clients = new Set<Socket>();
  private constructor(
    private readonly server: Server,
    readonly port: number,
  ) {}

  static async start(targetPort: number): Promise<Proxy> {
    const server = createServer();
    const port = await new Promise<number>((r) =>
      server.listen(0, '127.0.0.1', () => r((server.address() as { port: number }).port)),
    );
    const proxy = new Proxy(server, port);
    server.on('connection', (client) => {
      const upstream = connect(targetPort, '127.0.0.1');
      proxy.clients.add(client);
      client.on('error', () => upstream.destroy());
      upstream.on('error', () => client.destroy());
      client.on('close', () => {
        proxy.clients.delete(client);
        upstream.destroy();
      });
      client.on('data', (d: Buffer) => {
        if (proxy.swallow) proxy.swallowed += d.length;
        else upstream.write(d);
      });
      upstream.on('data', (d: Buffer) => client.write(d));
    });
    return proxy;
  }

  /** The connections open now lose everything sent on them from here on (no answer, no reset); new ones forward. */
  loseCurrent(): void {
    for (const c of this.clients) {
      c.removeAllListeners('data');
      c.on('data', (d: Buffer) => (this.swallowed += d.length));
    }
  }

  /** Resets every connection (RST, not FIN) and forwards again on the next ones. */
  reset(): void {
    this.swallow = false;
    for (const c of this.clients) c.resetAndDestroy();
  }

  close(): Promise<void> {
    for (const c of this.clients) c.destroy();
    return new Promise((r) => this.server.close(() => r()));
  }
}

describe('a connection reset while the safe write is on the wire', () => {
  let plant: PyModbusServer | undefined;
  let proxy: Proxy | undefined;
  let gw: RunningGateway | undefined;
  afterEach(async () => {
    await gw?.close();
    await proxy?.close();
    await plant?.kill();
  });

  it('is noticed at once: the shutdown reconnects and the device acknowledges the safe image', async () => {
    plant = await PyModbusServer.start(await freeLoopbackPort());
    proxy = await Proxy.start(plant.port);
    const lines: string[] = [];
    const config = resolveConfig({
      devices: [
        {
          id: 'plant',
          host: '127.0.0.1',
          port: proxy.port,
          pollMs: 20,
          timeoutMs: 200,
          points: [{ address: '%IX0.0' }, { address: '%QX0.0', count: 4 }],
        },
      ],
    });
    const running = await startGateway({ port: 0, config, distDir: null, log: (l) => lines.push(l) });
    gw = running;
    const c = await TestClient.armedController(running.port, running.token);
    c.send({ t: 'outputs', seq: 1, values: { '%QX0.0': true, '%QX0.2': true } });
    const p = plant;
    await eventually(async () => (await p.get('co', 0, 4)).join() === '1,0,1,0', 10_000, 'outputs ON');

    // The device stops answering; the controller stops: the safe write goes out and waits (up to 10 s).
    const px = proxy;
    px.swallow = true;
    px.swallowed = 0;
    c.send({ t: 'stop', seq: 2 });
    await eventually(() => Promise.resolve(px.swallowed > 0), 10_000, 'a request on the wire');
    // The connection is reset under it, and the gateway is told to exit right away.
    px.reset();
    gw = undefined;
    const report = await running.close();
    c.close();

    expect(report.devices).toEqual([expect.objectContaining({ id: 'plant', acknowledged: true })]);
    expect(report.safe).toBe(true);
    expect(await p.get('co', 0, 4)).toEqual([0, 0, 0, 0]);
  }, 30_000);

  it('a safe write the device lost (no answer, no reset) does not hold the shutdown past its deadline', async () => {
    plant = await PyModbusServer.start(await freeLoopbackPort());
    proxy = await Proxy.start(plant.port);
    const config = resolveConfig({
      devices: [
        {
          id: 'plant',
          host: '127.0.0.1',
          port: proxy.port,
          pollMs: 20,
          timeoutMs: 200,
          points: [{ address: '%IX0.0' }, { address: '%QX0.0', count: 4 }],
        },
      ],
    });
    const running = await startGateway({ port: 0, config, distDir: null, log: () => undefined });
    gw = running;
    const c = await TestClient.armedController(running.port, running.token);
    c.send({ t: 'outputs', seq: 1, values: { '%QX0.1': true } });
    const p = plant;
    await eventually(async () => (await p.get('co', 0, 4)).join() === '0,1,0,0', 10_000, 'outputs ON');

    const px = proxy;
    px.swallowed = 0;
    px.loseCurrent();
    c.send({ t: 'stop', seq: 2 });
    await eventually(() => Promise.resolve(px.swallowed > 0), 10_000, 'a request on the wire');
    gw = undefined;
    const report = await running.close();
    c.close();

    expect(report.safe).toBe(true);
    expect(await p.get('co', 0, 4)).toEqual([0, 0, 0, 0]);
  }, 30_000);
});
