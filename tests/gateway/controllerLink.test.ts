// Issue 21, the controller link: a gateway stall's backlog is not a flood (4), silent sockets cannot
// lock a controller out (6), observers hammering resync on a large map cannot starve the controller (7).
// Every case ends by reading the coils back from a real Modbus TCP server.
import { spawn } from 'node:child_process';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';
import { afterEach, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { MAX_CLIENTS, MAX_WAITING_FOR_HELLO, startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { RESYNC_BURST } from '../../src/gateway/session';
import { eventually, mbpoll, mbpollValues, PyModbusServer, TestClient } from './helpers';

const STEADY_CONTROLLER = fileURLToPath(new URL('./fixtures/steady_controller.mjs', import.meta.url));
const RESYNC_OBSERVERS = fileURLToPath(new URL('./fixtures/resync_observers.mjs', import.meta.url));

/** Coils of the simulated device's Modbus server, read with mbpoll. */
async function coils(port: number, from: number, count: number): Promise<number[]> {
  return mbpollValues(await mbpoll(port, ['-t', '0', '-r', String(from), '-c', String(count), '127.0.0.1']));
}

/** Blocks this process (and the gateway running in it) for `ms`, as a busy gateway would be. */
function stall(ms: number): void {
  const end = Date.now() + ms;
  while (Date.now() < end) {
    /* busy */
  }
}

describe('controller link (issue 21)', () => {
  let gw: RunningGateway | undefined;
  let plant: PyModbusServer | undefined;
  const clients: TestClient[] = [];
  afterEach(async () => {
    for (const c of clients.splice(0)) c.close();
    await gw?.close();
    gw = undefined;
    await plant?.kill();
    plant = undefined;
  });

  it('does not close a controller as a flooder for the messages that queued while the gateway was stalled', async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ watchdogMs: 5000, simulated: { modbusPort: 0 } }), distDir: null });
    const simPort = gw.simulated?.modbusServerPort;
    if (simPort === undefined) throw new Error('the simulated device has no Modbus server');
    // 150 outputs/s for 6 s from another process: below the 200/s budget, so never a flood by itself.
    const child = spawn(process.execPath, [STEADY_CONTROLLER, String(gw.port), gw.token, '%QX0.3', '150', '6'], { stdio: ['ignore', 'pipe', 'inherit'] });
    const lines: string[] = [];
    createInterface({ input: child.stdout }).on('line', (l) => lines.push(l));
    try {
      await eventually(() => lines.includes('ARMED'), 15_000, 'controller armed');
      await new Promise((r) => setTimeout(r, 500));
      // The gateway cannot read for 2.5 s; ~375 messages wait in the socket and arrive at once.
      stall(2500);
      await eventually(() => lines.some((l) => l.startsWith('DONE') || l.startsWith('CLOSED')), 20_000, 'controller finished');
      await eventually(async () => (await coils(simPort, 3, 1))[0] === 1, 10_000, 'the last image (coil 3 ON) on the device');
      expect(lines.filter((l) => l.startsWith('ERROR') || l.startsWith('CLOSED'))).toEqual([]);
    } finally {
      child.kill();
    }
  });

  it(`lets a controller in at once while more than ${MAX_CLIENTS} sockets that never say hello are open`, async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: 0 } }), distDir: null });
    const simPort = gw.simulated?.modbusServerPort;
    if (simPort === undefined) throw new Error('the simulated device has no Modbus server');
    const silent = MAX_WAITING_FOR_HELLO + 4;
    for (let i = 0; i < silent; i++) clients.push(await TestClient.connect(gw.port));
    // No retry: the first attempt gets the lease.
    const controller = await TestClient.hello(gw.port, gw.token, 'controller');
    clients.push(controller);
    expect(controller.messages.find((m) => m.t === 'welcome')).toMatchObject({ role: 'controller' });
    // The silent sockets that waited longest gave way (1013, try again later) rather than the newcomer.
    await eventually(() => clients.filter((c) => c.closeCode === 1013).length >= silent + 1 - MAX_WAITING_FOR_HELLO, 5000, 'oldest silent sockets closed');
    await controller.arm();
    controller.send({ t: 'outputs', seq: 1, values: { '%QX0.5': true } });
    await eventually(async () => (await coils(simPort, 5, 1))[0] === 1, 5000, 'coil 5 ON on the device');
    // Observers still have their limit: the controller plus MAX_CLIENTS - 1 observers fill the gateway.
    for (let i = 1; i < MAX_CLIENTS; i++) clients.push(await TestClient.hello(gw.port, gw.token, 'observer'));
    await expect(TestClient.connect(gw.port)).rejects.toThrow('HTTP 503');
    controller.send({ t: 'stop' });
    await eventually(async () => (await coils(simPort, 5, 1))[0] === 0, 5000, 'coil 5 OFF after stop');
  });

  it('keeps a controller fed and connected while 3 observers hammer resync of a 3,648-point map', async () => {
    const modbusPort = await freeLoopbackPort();
    plant = await PyModbusServer.start(modbusPort);
    // The OpenPLC default map in full: 800 + 800 bits, 1,024 + 1,024 registers.
    const config = resolveConfig({
      watchdogMs: 1000,
      devices: [
        {
          id: 'plant',
          host: '127.0.0.1',
          port: modbusPort,
          pollMs: 100,
          timeoutMs: 1000,
          points: [
            { address: '%IX0.0', count: 800 },
            { address: '%QX0.0', count: 800 },
            { address: '%IW0', count: 1024 },
            { address: '%QW0', count: 1024 },
          ],
        },
      ],
    });
    gw = await startGateway({ port: 0, config, distDir: null });
    const controller = await TestClient.hello(gw.port, gw.token, 'controller');
    clients.push(controller);
    const welcome = controller.messages.find((m) => m.t === 'welcome');
    expect(welcome?.t === 'welcome' && welcome.points.length).toBe(3648);
    await controller.arm(15_000);
    // Three observers in another process (as other pages or tools would be): 150 resync/s each for 5 s.
    const hammer = spawn(process.execPath, [RESYNC_OBSERVERS, String(gw.port), gw.token, '3', '150', '5'], { stdio: ['ignore', 'pipe', 'inherit'] });
    const lines: string[] = [];
    createInterface({ input: hammer.stdout }).on('line', (l) => lines.push(l));
    let scan = 0;
    try {
      await eventually(() => lines.includes('READY'), 15_000, 'observers welcomed');
      // The controller meanwhile: 20 scans/s toggling %QX0.7, ending ON.
      const scans = setInterval(() => {
        scan++;
        controller.send({ t: 'outputs', seq: scan, values: { '%QX0.7': scan % 2 === 1 } });
      }, 50);
      try {
        await eventually(() => lines.length >= 4, 30_000, 'observers finished');
      } finally {
        clearInterval(scans);
      }
    } finally {
      hammer.kill();
    }
    if (scan % 2 === 0) controller.send({ t: 'outputs', seq: ++scan, values: { '%QX0.7': true } });
    await eventually(async () => (await plant!.get('co', 7, 1))[0] === 1, 10_000, 'coil 7 ON on the device');

    // The controller was never closed, never refused, and the watchdog never tripped.
    expect(controller.closeCode).toBeUndefined();
    expect(controller.messages.filter((m) => m.t === 'error')).toEqual([]);
    expect(controller.messages.some((m) => m.t === 'status' && m.watchdog.state === 'tripped')).toBe(false);
    expect(controller.lastStatus()).toMatchObject({ armed: true, watchdog: { state: 'fed' } });
    // Every observer sent its 750 resyncs and was answered politely: images within its budget, the
    // rest "too often"; none was closed.
    const report = lines.slice(1).map((l) => JSON.parse(l) as { sent: number; images: number; tooOften: number; errors: Record<string, number>; closed: number | null });
    expect(report).toHaveLength(3);
    for (const r of report) {
      expect(r).toMatchObject({ sent: 750, errors: {}, closed: null });
      expect(r.images).toBeGreaterThanOrEqual(RESYNC_BURST);
      expect(r.images - 1 + r.tooOften).toBe(750); // the first image came with the welcome
    }
    controller.send({ t: 'stop' });
    await eventually(async () => (await plant!.get('co', 7, 1))[0] === 0, 10_000, 'coil 7 OFF after stop');
  }, 60_000);
});
