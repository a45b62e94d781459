// The gateway against an independent Modbus TCP server (Debian's python3-pymodbus), end to end over ws.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { eventually, PyModbusServer, TestClient } from './helpers';

const WATCHDOG_MS = 500;
const POLL_MS = 50;

describe('gateway with a Modbus TCP device', () => {
  let plant: PyModbusServer;
  let gw: RunningGateway;
  let modbusPort: number;

  beforeAll(async () => {
    modbusPort = await freeLoopbackPort();
    plant = await PyModbusServer.start(modbusPort);
    const config = resolveConfig({
      watchdogMs: WATCHDOG_MS,
      devices: [
        {
          id: 'plant',
          host: '127.0.0.1',
          port: modbusPort,
          unitId: 1,
          pollMs: POLL_MS,
          timeoutMs: 300,
          points: [
            { address: '%IX0.0', count: 8 },
            { address: '%QX0.0', count: 8 },
            { address: '%QX1.0', hold: true },
            { address: '%IW0', count: 2, type: 'INT' },
            { address: '%QW0', count: 2 },
          ],
        },
      ],
    });
    gw = await startGateway({ port: 0, config, distDir: null });
  });

  afterAll(async () => {
    await gw?.close();
    await plant?.kill();
  });

  it('welcomes a controller with the configured points of the device', async () => {
    const c = await TestClient.armedController(gw.port, gw.token);
    const welcome = c.messages.find((m) => m.t === 'welcome');
    expect(welcome).toMatchObject({ role: 'controller', devices: [{ id: 'plant', kind: 'modbus-tcp' }] });
    expect(welcome?.t === 'welcome' && welcome.points.map((p) => p.address)).toEqual([
      ...['%IX0.0', '%IX0.1', '%IX0.2', '%IX0.3', '%IX0.4', '%IX0.5', '%IX0.6', '%IX0.7'],
      ...['%QX0.0', '%QX0.1', '%QX0.2', '%QX0.3', '%QX0.4', '%QX0.5', '%QX0.6', '%QX0.7'],
      '%QX1.0',
      '%IW0',
      '%IW1',
      '%QW0',
      '%QW1',
    ]);
    c.close();
  });

  it('reads inputs the Modbus server changes and writes outputs into its coils and registers', async () => {
    const c = await TestClient.armedController(gw.port, gw.token);
    await eventually(() => c.messages.some((m) => m.t === 'status' && m.devices[0]?.state === 'online'), 3000, 'device online');
    await plant.set('di', 3, [1]);
    await plant.set('ir', 1, [65535]); // -1 as INT
    await eventually(() => c.values()['%IX0.3'] === true && c.values()['%IW1'] === -1, 3000, 'inputs seen');
    expect(c.quality()['%IX0.3']).toBe('good');

    c.send({ t: 'outputs', seq: 1, values: { '%QX0.0': true, '%QX0.5': true, '%QW1': 4242 } });
    await eventually(async () => (await plant.get('co', 0, 8)).join() === '1,0,0,0,0,1,0,0', 3000, 'coils written');
    expect(await plant.get('hr', 0, 2)).toEqual([0, 4242]);
    await eventually(() => c.values()['%QX0.5'] === true, 3000, 'written echoed');
    c.send({ t: 'stop', seq: 2 });
    await eventually(async () => (await plant.get('co', 0, 8)).every((v) => v === 0), 3000, 'stop -> safe state');
    c.close();
  });

  it('a coil changed behind its back (a coupler that cleared it, or another master) disarms instead of being fought over; arm rewrites it', async () => {
    const c = await TestClient.armedController(gw.port, gw.token);
    c.send({ t: 'outputs', seq: 1, values: { '%QX0.2': true } });
    await eventually(async () => (await plant.get('co', 2, 1))[0] === 1, 3000, 'coil on');
    const mark = c.messages.length;
    const feed = setInterval(() => c.send({ t: 'outputs', seq: 2, values: { '%QX0.2': true } }), 50);
    try {
      // The coupler clears its coil (its own watchdog, a restart, a panel); again if the gateway's
      // rewrite happened to land right after it (between its read-back and its write, GATEWAY.md).
      const seen = () => c.messages.slice(mark).some((m) => m.t === 'status' && m.disarm?.cause === 'other-master');
      for (let i = 0; i < 50 && !seen(); i++) {
        await plant.set('co', 2, [0]);
        await new Promise((r) => setTimeout(r, 2 * POLL_MS));
      }
      const s = await c.waitFor((m) => m.t === 'status' && m.disarm?.cause === 'other-master', 5000, mark);
      expect(s.t === 'status' && s.disarm?.message).toContain('another Modbus master is writing device "plant"\'s outputs (%QX0.2 read back OFF, we wrote ON): disarmed');
      // Not rewritten ON by the running program: the gateway is disarmed and leaves the outputs alone.
      for (let i = 0; i < 5; i++) {
        await new Promise((r) => setTimeout(r, POLL_MS));
        expect(await plant.get('co', 2, 1)).toEqual([0]);
      }
      // The operator arms again (once the outputs stay still): the program's image is written again, every poll.
      await eventually(
        async () => {
          const from = c.messages.length;
          c.send({ t: 'arm' });
          const r = await c.waitFor((m) => (m.t === 'status' && m.armed) || (m.t === 'error' && m.code === 'arm-refused'), 5000, from);
          return r.t === 'status';
        },
        10_000,
        'armed again',
      );
      await eventually(async () => (await plant.get('co', 2, 1))[0] === 1, 3000, 'coil rewritten');
    } finally {
      clearInterval(feed);
      c.send({ t: 'stop' });
      c.close();
    }
  });

  it('drives every coil to 0 when the lease expires, except hold points, and stays disarmed until arm', async () => {
    const c = await TestClient.armedController(gw.port, gw.token);
    c.send({ t: 'arm' });
    c.send({ t: 'outputs', seq: 10, values: { '%QX0.0': true, '%QX0.1': true, '%QX0.7': true, '%QX1.0': true, '%QW0': 7 } });
    await eventually(async () => (await plant.get('co', 0, 9)).join() === '1,1,0,0,0,0,0,1,1', 3000, 'coils on');
    // No more outputs: the watchdog must trip and write the safe state.
    await eventually(async () => (await plant.get('co', 0, 8)).every((v) => v === 0), WATCHDOG_MS + POLL_MS + 1000, 'safe state');
    expect(await plant.get('co', 8, 1)).toEqual([1]); // %QX1.0 is configured hold
    expect(await plant.get('hr', 0, 1)).toEqual([0]);
    const tripped = await c.waitFor((m) => m.t === 'status' && m.watchdog.state === 'tripped');
    expect(tripped).toMatchObject({ armed: false });

    const before = c.messages.length;
    c.send({ t: 'outputs', seq: 11, values: { '%QX0.0': true } });
    const refusal = await c.waitFor((m) => m.t === 'error', 3000, before);
    expect(refusal).toMatchObject({ code: 'disarmed', ref: 11 });
    expect(await plant.get('co', 0, 1)).toEqual([0]);

    c.send({ t: 'arm' });
    await c.waitFor((m) => m.t === 'status' && m.armed, 3000, before);
    c.send({ t: 'outputs', seq: 12, values: { '%QX0.0': true } });
    await eventually(async () => (await plant.get('co', 0, 1))[0] === 1, 3000, 'outputs resume after arm');
    c.send({ t: 'stop' });
    c.close();
  });

  it('marks the device offline and its inputs stale when the server dies, and recovers when it returns', async () => {
    const c = await TestClient.hello(gw.port, gw.token, 'observer');
    await plant.set('di', 0, [1]);
    await eventually(() => c.values()['%IX0.0'] === true, 3000, 'input read');
    await plant.kill();
    const offline = await c.waitFor((m) => m.t === 'status' && m.devices[0]?.state === 'offline', 5000);
    expect(offline.t === 'status' && offline.devices[0]?.error).toBeTruthy();
    await eventually(() => c.quality()['%IX0.0'] === 'stale' && c.quality()['%IW0'] === 'stale', 3000, 'stale inputs');
    expect(c.values()['%IX0.0']).toBe(true); // last value kept, but marked stale

    plant = await PyModbusServer.start(modbusPort);
    await plant.set('di', 0, [0, 1]);
    await c.waitFor((m) => m.t === 'status' && m.devices[0]?.state === 'online', 10_000);
    await eventually(() => c.quality()['%IX0.0'] === 'good' && c.values()['%IX0.1'] === true, 3000, 'fresh inputs');
    c.close();
  });
});
