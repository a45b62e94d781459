// Issue 10, "outputs left ON": every case against a real Modbus TCP server (Debian's pymodbus),
// asserting the coils read back from the device. A controller keeps sending outputs ON at 100 Hz
// (a running program) throughout, so nothing but the gateway's latch can keep them off.
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import type { GatewayMessage } from '../../src/protocol/messages';
import { CuttableLink, eventually, PyModbusServer, readWriteLog, TestClient } from './helpers';

const POLL_MS = 50;
const ON = { '%QX0.0': true, '%QX0.1': true, '%QW0': 1234 } as const;

type Status = Extract<GatewayMessage, { t: 'status' }>;

interface Rig {
  plant: PyModbusServer;
  modbusPort: number;
  link?: CuttableLink;
  gw: RunningGateway;
  log: string;
}

/** A running program: the controller sends the same ON image every 10 ms until stopped. */
function run100Hz(c: TestClient, values: Record<string, boolean | number> = ON): () => void {
  let seq = 0;
  const timer = setInterval(() => c.send({ t: 'outputs', seq: ++seq, values }), 10);
  return () => clearInterval(timer);
}

const coils = (plant: PyModbusServer) => plant.get('co', 0, 2);
const isOn = async (plant: PyModbusServer) => (await coils(plant)).join() === '1,1' && (await plant.get('hr', 0, 1))[0] === 1234;
const isOff = async (plant: PyModbusServer) => (await coils(plant)).join() === '0,0' && (await plant.get('hr', 0, 1))[0] === 0;
/** The first status from message `from` on that matches (statuses before the fault do not count). */
const statusWhere = (c: TestClient, from: number, pred: (s: Status) => boolean, timeoutMs = 8000) =>
  c.waitFor((m): m is Status => m.t === 'status' && pred(m), timeoutMs, from);

/** Waits `polls` poll periods while the program keeps asking for ON; the device must stay OFF. */
async function staysOff(plant: PyModbusServer, polls: number): Promise<void> {
  for (let i = 0; i < polls; i++) {
    await new Promise((r) => setTimeout(r, POLL_MS));
    expect(await isOff(plant)).toBe(true);
  }
}

describe('outputs never left ON (issue 10, cases 1, 3, 4)', () => {
  let rig: Rig | undefined;
  const clients: TestClient[] = [];
  const stops: (() => void)[] = [];

  async function setUp(opts: { viaLink?: boolean; watchdogMs?: number; timeoutMs?: number } = {}): Promise<Rig> {
    const modbusPort = await freeLoopbackPort();
    const log = join(mkdtempSync(join(tmpdir(), 'rungsmith-safety-')), 'writes.log');
    const plant = await PyModbusServer.start(modbusPort, log);
    const link = opts.viaLink ? await CuttableLink.open(modbusPort) : undefined;
    const config = resolveConfig({
      watchdogMs: opts.watchdogMs ?? 1000,
      devices: [
        {
          id: 'plant',
          host: '127.0.0.1',
          port: link?.port ?? modbusPort,
          pollMs: POLL_MS,
          timeoutMs: opts.timeoutMs ?? 300,
          points: [{ address: '%IX0.0' }, { address: '%QX0.0', count: 2 }, { address: '%QW0' }],
        },
      ],
    });
    const gw = await startGateway({ port: 0, config, distDir: null });
    rig = { plant, modbusPort, link, gw, log };
    return rig;
  }

  async function armedAndOn(r: Rig): Promise<TestClient> {
    const c = await TestClient.armedController(r.gw.port, r.gw.token);
    clients.push(c);
    stops.push(run100Hz(c));
    await eventually(() => isOn(r.plant), 3000, 'outputs ON on the device');
    return c;
  }

  /** Writes of anything but zeros that reached the device after `since`. */
  const onWritesSince = (r: Rig, since: number) => readWriteLog(r.log).filter((w) => w.at >= since && w.values.some((v) => v !== 0));

  afterEach(async () => {
    stops.splice(0).forEach((s) => s());
    clients.splice(0).forEach((c) => c.close());
    if (rig) {
      await rig.gw.close();
      await rig.link?.close();
      await rig.plant.kill();
      rig = undefined;
    }
  });

  it('1. STOP while the device is unreachable (cable cut): the safe state is retried and written when it comes back', async () => {
    const r = await setUp({ viaLink: true });
    const c = await armedAndOn(r);
    const mark = c.messages.length;
    r.link!.sever();
    c.send({ t: 'stop', seq: 1 });
    const pending = await statusWhere(c, mark, (s) => !s.armed && s.devices[0]?.outputs === 'safe-pending');
    expect(pending.disarm?.cause).toMatch(/device-lost|stop/);
    // The device kept its outputs ON: nothing could reach it.
    expect(await isOn(r.plant)).toBe(true);
    await new Promise((res) => setTimeout(res, 4 * POLL_MS));
    r.link!.restore();
    await eventually(() => isOff(r.plant), 8000, 'safe state written after the device came back');
    await statusWhere(c, mark, (s) => s.devices[0]?.outputs === 'safe' && !s.armed);
    await staysOff(r.plant, 6);
  });

  it('1. the browser stops (the lease expires) while the device answers with Modbus exceptions: written once it answers again', async () => {
    const r = await setUp({ watchdogMs: 300 });
    const c = await armedAndOn(r);
    const mark = c.messages.length;
    await r.plant.mode('exception');
    stops.splice(0).forEach((s) => s()); // the browser stops sending: the lease expires
    await statusWhere(c, mark, (s) => !s.armed && s.devices[0]?.outputs === 'safe-pending');
    expect(await isOn(r.plant)).toBe(true); // every write was refused by the device
    const restartedAt = Date.now();
    await r.plant.mode('normal');
    await eventually(() => isOff(r.plant), 5000, 'safe state written after the exceptions ended');
    await statusWhere(c, mark, (s) => s.devices[0]?.outputs === 'safe');
    expect(onWritesSince(r, restartedAt)).toEqual([]);
  });

  it('1. the controller disconnects while the device is slow (2 s per answer): written when it is fast again', async () => {
    const r = await setUp();
    const c = await armedAndOn(r);
    const observer = await TestClient.hello(r.gw.port, r.gw.token, 'observer');
    clients.push(observer);
    await r.plant.mode('slow', 2000);
    stops.splice(0).forEach((s) => s());
    c.close();
    await statusWhere(observer, 0, (s) => !s.armed && s.devices[0]?.outputs === 'safe-pending');
    await new Promise((res) => setTimeout(res, 1000)); // requests time out meanwhile (300 ms)
    expect(await isOn(r.plant)).toBe(true);
    const mark = observer.messages.length;
    await r.plant.mode('normal');
    await eventually(() => isOff(r.plant), 8000, 'safe state written after the device sped up');
    await statusWhere(observer, mark, (s) => s.devices[0]?.outputs === 'safe' && !s.armed);
  });

  it('3. a device that power-cycles is not given its old outputs back: disarmed, and ON again only after Arm', async () => {
    const r = await setUp();
    const c = await armedAndOn(r);
    const mark = c.messages.length;
    await r.plant.kill();
    const lost = await statusWhere(c, mark, (s) => !s.armed);
    expect(lost.disarm).toMatchObject({ cause: 'device-lost' });
    expect(lost.disarm?.message).toMatch(/device "plant"/);
    const restartedAt = Date.now();
    r.plant = await PyModbusServer.start(r.modbusPort, r.log);
    await statusWhere(c, mark, (s) => s.devices[0]?.state === 'online' && s.devices[0]?.outputs === 'safe', 15_000);
    await staysOff(r.plant, 8); // the program kept asking for ON the whole time
    expect(onWritesSince(r, restartedAt)).toEqual([]);
    expect(readWriteLog(r.log).filter((w) => w.at >= restartedAt).length).toBeGreaterThan(0); // the safe image was written

    await c.arm();
    await eventually(() => isOn(r.plant), 3000, 'outputs after a deliberate arm');
  });

  it('3. a device that comes back after an outage without restarting gets the safe state, not the last outputs', async () => {
    const r = await setUp({ viaLink: true });
    const c = await armedAndOn(r);
    const mark = c.messages.length;
    r.link!.sever();
    await statusWhere(c, mark, (s) => !s.armed && s.disarm?.cause === 'device-lost');
    r.link!.restore();
    await eventually(() => isOff(r.plant), 8000, 'safe image written on reconnect');
    await staysOff(r.plant, 8);
    expect(c.lastStatus()).toMatchObject({ armed: false, disarm: { cause: 'device-lost' } });
    const arm = c.messages.length;
    await c.arm();
    expect(c.messages.slice(arm).some((m) => m.t === 'error')).toBe(false);
    await eventually(() => isOn(r.plant), 3000, 'outputs after a deliberate arm');
  });

  it('4. STOP latches: outputs sent after STOP are refused until an explicit arm', async () => {
    const r = await setUp();
    const c = await armedAndOn(r);
    const from = c.messages.length;
    c.send({ t: 'stop', seq: 1 });
    await eventually(() => isOff(r.plant), 3000, 'safe state after STOP');
    await staysOff(r.plant, 8);
    const refusals = c.messages.slice(from).filter((m) => m.t === 'error');
    expect(refusals.length).toBe(1); // said once, not once per scan
    expect(refusals[0]).toMatchObject({ code: 'disarmed' });
    expect(refusals[0]?.t === 'error' && refusals[0].message).toMatch(/STOP/);
    expect(c.lastStatus()).toMatchObject({ armed: false, disarm: { cause: 'stop' }, devices: [{ outputs: 'safe' }] });
    await c.arm();
    await eventually(() => isOn(r.plant), 3000, 'outputs after arm');
  });

  it('arm is refused while a device is not online, with the reason', async () => {
    const r = await setUp({ viaLink: true });
    const c = await armedAndOn(r);
    const mark = c.messages.length;
    r.link!.sever();
    await statusWhere(c, mark, (s) => s.devices[0]?.state === 'offline');
    const from = c.messages.length;
    c.send({ t: 'arm', seq: 7 });
    const refused = await c.waitFor((m) => m.t === 'error' && m.ref === 7, 3000, from);
    expect(refused).toMatchObject({ code: 'arm-refused' });
    expect(refused.t === 'error' && refused.message).toMatch(/"plant" is offline/);
    expect(c.lastStatus()?.armed).toBe(false);
  });
});
