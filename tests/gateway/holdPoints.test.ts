// `hold` outputs (GATEWAY-CONFIG.md: "in the safe state keep the last value instead of OFF/0, e.g. a
// valve that must not move on a communication loss") against Debian's pymodbus server, read back
// from the server itself and from its write log, never from the gateway's view.
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import WebSocket from 'ws';
import { afterEach, expect, it } from 'vitest';
import { GatewayBridge } from '../../src/bridge/GatewayBridge';
import { GatewayClient, type SocketLike } from '../../src/bridge/GatewayClient';
import { checkBindings } from '../../src/bridge/mapping';
import { GatewayRelay } from '../../src/bridge/workerRelay';
import { workerDriver, workerSocketFactory } from '../../src/bridge/workerSocket';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { SimTransport } from '../../src/sim/host';
import type { SimFrame, WorkerMessage } from '../../src/sim/protocol';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import type { GatewayMessage } from '../../src/protocol/messages';
import { eventually, PyModbusServer, readWriteLog, TestClient } from './helpers';

const POLL_MS = 50;
let plant: PyModbusServer | undefined;
let gw: RunningGateway | undefined;
const clients: TestClient[] = [];
afterEach(async () => {
  clients.splice(0).forEach((c) => c.close());
  await gw?.close();
  await plant?.kill();
  gw = undefined;
  plant = undefined;
});

type Status = Extract<GatewayMessage, { t: 'status' }>;

type Point = { address: string; hold?: boolean; count?: number };
/** The gateway started with the pymodbus server at `modbusPort` as its device "plant", with these points. */
async function startBeside(modbusPort: number, points: Point[], watchdogMs?: number): Promise<RunningGateway> {
  const config = resolveConfig({
    ...(watchdogMs !== undefined ? { watchdogMs } : {}),
    devices: [{ id: 'plant', host: '127.0.0.1', port: modbusPort, pollMs: POLL_MS, timeoutMs: 300, points }],
  });
  return startGateway({ port: 0, config, distDir: null });
}

async function rig() {
  const modbusPort = await freeLoopbackPort();
  const log = join(mkdtempSync(join(tmpdir(), 'rungsmith-hold-')), 'writes.log');
  plant = await PyModbusServer.start(modbusPort, log);
  // %QX0.0 a motor (OFF in the safe state), %QX0.1 a valve that must not move (hold).
  gw = await startBeside(modbusPort, [{ address: '%IX0.0' }, { address: '%QX0.0' }, { address: '%QX0.1', hold: true }], 1000);
  return { modbusPort, log };
}

it('a device that power-cycles is not given its hold output back: the valve the restart dropped stays OFF until Arm (nothing is re-energised while disarmed)', async () => {
  const { modbusPort, log } = await rig();
  const c = await TestClient.armedController(gw!.port, gw!.token);
  clients.push(c);
  let seq = 0;
  const program = setInterval(
    () => c.send({ t: 'outputs', seq: ++seq, values: { '%QX0.0': true, '%QX0.1': true } }),
    10,
  );
  try {
    await eventually(async () => (await plant!.get('co', 0, 2)).join() === '1,1', 5000, 'motor and valve ON');
    const mark = c.messages.length;
    await plant!.kill(); // the coupler power-cycles: its outputs drop
    await c.waitFor((m): m is Status => m.t === 'status' && !m.armed, 8000, mark);
    const restartedAt = Date.now();
    plant = await PyModbusServer.start(modbusPort, log);
    await c.waitFor(
      (m): m is Status =>
        m.t === 'status' && m.devices[0]?.state === 'online' && m.devices[0]?.outputs === 'safe',
      15_000,
      mark,
    );
    for (let i = 0; i < 8; i++) {
      await new Promise((r) => setTimeout(r, POLL_MS));
      expect(await plant.get('co', 0, 2)).toEqual([0, 0]); // the program kept asking for ON all along
    }
    const onWrites = readWriteLog(log).filter((w) => w.at >= restartedAt && w.values.some((v) => v !== 0));
    expect(onWrites).toEqual([]);
    await c.arm();
    await eventually(
      async () => (await plant!.get('co', 0, 2)).join() === '1,1',
      5000,
      'ON again after a deliberate arm',
    );
  } finally {
    clearInterval(program);
  }
}, 60_000);

it('a hold output keeps its value through STOP and the watchdog; the motor beside it goes OFF', async () => {
  await rig();
  const c = await TestClient.armedController(gw!.port, gw!.token);
  clients.push(c);
  c.send({ t: 'outputs', seq: 1, values: { '%QX0.0': true, '%QX0.1': true } });
  await eventually(async () => (await plant!.get('co', 0, 2)).join() === '1,1', 5000, 'motor and valve ON');
  c.send({ t: 'stop', seq: 2 });
  await eventually(
    async () => (await plant!.get('co', 0, 2)).join() === '0,1',
    5000,
    'STOP: motor OFF, valve held',
  );
  await c.arm();
  c.send({ t: 'outputs', seq: 3, values: { '%QX0.0': true, '%QX0.1': false } });
  await eventually(
    async () => (await plant!.get('co', 0, 2)).join() === '1,0',
    5000,
    'motor ON, valve closed',
  );
  // The watchdog (no outputs for 1 s): the motor OFF, the valve stays as it was (closed).
  await eventually(async () => (await plant!.get('co', 0, 2)).join() === '0,0', 5000, 'watchdog: motor OFF');
}, 60_000);

it('a gateway started next to a held valve leaves it as the device holds it; the motor is switched off', async () => {
  const modbusPort = await freeLoopbackPort();
  plant = await PyModbusServer.start(modbusPort);
  await plant.set('co', 0, [1, 1]); // what a previous run left
  gw = await startBeside(modbusPort, [{ address: '%QX0.0' }, { address: '%QX0.1', hold: true }]);
  const o = await TestClient.hello(gw.port, gw.token, 'observer');
  clients.push(o);
  await o.waitFor((m): m is Status => m.t === 'status' && m.devices[0]?.outputs === 'safe', 10_000);
  expect(await plant.get('co', 0, 2)).toEqual([0, 1]);
}, 60_000);

it('an online change that moves the valve (hold) and the motor off their outputs: the motor output goes OFF, the held valve keeps its value, as in the safe state', async () => {
  const modbusPort = await freeLoopbackPort();
  plant = await PyModbusServer.start(modbusPort);
  gw = await startBeside(modbusPort, [{ address: '%QX0.0' }, { address: '%QX0.1', hold: true }, { address: '%QX0.2', count: 2 }]);
  // The worker's relay and the page's transport to it, as the simulator's worker and host join them.
  const listeners = new Set<(m: WorkerMessage) => void>();
  const relay = new GatewayRelay(
    (m) => listeners.forEach((l) => l(m)),
    (url) => new WebSocket(url) as unknown as SocketLike,
    {
      setInputs: () => undefined,
      wantOutputs: () => undefined,
    },
  );
  const transport: SimTransport = {
    send: (m) => {
      if (m.type.startsWith('gw'))
        queueMicrotask(() => relay.handle(m as Parameters<GatewayRelay['handle']>[0]));
    },
    listen: (l) => {
      listeners.add(l);
      return () => listeners.delete(l);
    },
    terminate: () => undefined,
  };
  const client = new GatewayClient({
    socketUrl: `ws://127.0.0.1:${gw.port}/io`,
    token: gw.token,
    role: 'controller',
    socketFactory: workerSocketFactory(transport),
  });
  client.connect();
  try {
    await eventually(
      () => client.snapshot.link === 'open' && client.snapshot.status?.devices[0]?.state === 'online',
      5000,
      'open, device online',
    );
    const bridge = new GatewayBridge(client, workerDriver(transport));
    transport.send({ type: 'gwPrograms', ids: ['P'] });
    bridge.requestArm();
    const project = newProject('P', {
      pous: [
        newPou('Main', {
          variables: [
            variable('Motor', 'BOOL', { location: '%QX0.0' }),
            variable('Valve', 'BOOL', { location: '%QX0.1' }),
          ],
        }),
      ],
    });
    bridge.attach(
      { setInputs: () => undefined, onOutputs: () => () => undefined },
      checkBindings(project, client.snapshot.points).bindings,
    );
    relay.frame({ mode: 'running' } as SimFrame);
    await eventually(() => client.snapshot.status?.armed === true, 5000, 'armed');
    relay.outputs({ '%QX0.0': true, '%QX0.1': true }, 'P');
    await eventually(
      async () => (await plant!.get('co', 0, 4)).join() === '1,1,0,0',
      5000,
      'motor and valve ON',
    );

    // Applied online: Motor now at %QX0.3, Valve at %QX0.2.
    transport.send({ type: 'gwPrograms', ids: ['P2'] });
    await new Promise((r) => queueMicrotask(() => r(undefined)));
    relay.outputs({ '%QX0.2': true, '%QX0.3': true }, 'P2');
    await eventually(
      async () => (await plant!.get('co', 2, 2)).join() === '1,1',
      5000,
      'both at their new addresses',
    );
    await eventually(async () => (await plant!.get('co', 0, 1))[0] === 0, 5000, "the motor's old output OFF");
    for (let i = 0; i < 6; i++) {
      relay.outputs({ '%QX0.2': true, '%QX0.3': true }, 'P2');
      await new Promise((r) => setTimeout(r, POLL_MS));
      expect(await plant.get('co', 0, 4)).toEqual([0, 1, 1, 1]); // the held valve did not move
    }
    relay.frame({ mode: 'paused' } as SimFrame);
    await eventually(
      async () => (await plant!.get('co', 0, 4)).join() === '0,1,0,0',
      5000,
      'STOP: OFF but the held valve',
    );
  } finally {
    client.disconnect();
  }
}, 60_000);

it('a slow device (1.5 s per answer, timeout 300 ms) with a hold output still gets the safe state on a new connection: the hold read waits as the safe write does', async () => {
  const modbusPort = await freeLoopbackPort();
  plant = await PyModbusServer.start(modbusPort);
  await plant.set('co', 0, [1, 1]); // what a previous run left: motor and valve ON
  await plant.mode('slow', 1500);
  gw = await startBeside(modbusPort, [{ address: '%QX0.0' }, { address: '%QX0.1', hold: true }]);
  const o = await TestClient.hello(gw.port, gw.token, 'observer');
  clients.push(o);
  await o.waitFor((m): m is Status => m.t === 'status' && m.devices[0]?.outputs === 'safe', 30_000);
  await plant.mode('normal');
  expect(await plant.get('co', 0, 2)).toEqual([0, 1]);
}, 60_000);
