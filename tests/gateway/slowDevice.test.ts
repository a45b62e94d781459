// Issue 21.3: a device that answers slower than the request timeout still receives the safe image.
// STOP, a watchdog trip and the controller disconnecting while pymodbus answers every request only
// after SLOW_MS (3x timeoutMs): the pending safe write keeps its connection and waits for the answer
// (up to safeWriteTimeoutMs), the coils read back OFF while the device is still slow, the device's
// write log ends with the safe image, and status said how long the safe state was pending.
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import type { GatewayMessage } from '../../src/protocol/messages';
import { eventually, PyModbusServer, readWriteLog, TestClient } from './helpers';

const TIMEOUT_MS = 400;
const SLOW_MS = 1200;
const ON = { '%QX0.0': true, '%QX0.1': true, '%QX0.2': true, '%QW0': 4321 } as const;
type Status = Extract<GatewayMessage, { t: 'status' }>;

describe('a slow device gets the safe image while it stays slow (issue 21.3)', () => {
  let plant: PyModbusServer | undefined;
  let gw: RunningGateway | undefined;
  const timers: NodeJS.Timeout[] = [];
  afterEach(async () => {
    timers.splice(0).forEach((t) => clearInterval(t));
    await plant?.mode('normal').catch(() => undefined);
    await gw?.close();
    await plant?.kill();
  });

  async function rig(watchdogMs = 5000, timeoutMs = TIMEOUT_MS) {
    const modbusPort = await freeLoopbackPort();
    const writeLog = join(mkdtempSync(join(tmpdir(), 'rungsmith-slow-')), 'writes.log');
    plant = await PyModbusServer.start(modbusPort, writeLog);
    const lines: string[] = [];
    const config = resolveConfig({
      watchdogMs,
      devices: [
        {
          id: 'plant',
          host: '127.0.0.1',
          port: modbusPort,
          pollMs: 50,
          timeoutMs,
          safeWriteTimeoutMs: 8000,
          points: [{ address: '%IX0.0' }, { address: '%QX0.0', count: 4 }, { address: '%QW0' }],
        },
      ],
    });
    gw = await startGateway({ port: 0, config, distDir: null, log: (l) => lines.push(l) });
    const c = await TestClient.armedController(gw.port, gw.token);
    const scans = setInterval(() => c.send({ t: 'outputs', seq: 1, values: ON }), 10);
    timers.push(scans);
    const p = plant;
    await eventually(async () => (await p.get('co', 0, 4)).join() === '1,1,1,0' && (await p.get('hr', 0, 1))[0] === 4321, 10_000, 'outputs ON');
    return { c, plant: p, writeLog, lines, scans };
  }

  // The trip case: the lease (300 ms) runs out before a request to the slow device times out (1000 ms),
  // so the watchdog, not the lost device, is what asks for the safe state.
  it.each([
    ['STOP', 5000, TIMEOUT_MS, SLOW_MS],
    ['a watchdog trip', 300, 1000, 2500],
    ['the controller disconnecting', 5000, TIMEOUT_MS, SLOW_MS],
  ] as const)('%s while the device answers in 2.5-3x the timeout: coils OFF, safe write acknowledged', async (what, watchdogMs, timeoutMs, slowMs) => {
    const { c, plant: p, writeLog, lines, scans } = await rig(watchdogMs, timeoutMs);
    await p.mode('slow', slowMs);
    const since = Date.now();
    const mark = c.messages.length;
    if (what === 'STOP') c.send({ t: 'stop', seq: 2 });
    else clearInterval(scans); // the program stops sending: the lease runs out
    if (what === 'the controller disconnecting') c.close();
    // Watched by an observer, so the disconnect case can be followed too.
    const o = await TestClient.hello(gw!.port, gw!.token, 'observer');
    const observed = what === 'the controller disconnecting' ? o : c;
    const from = observed === c ? mark : 0;
    // Still slow: the coils must go OFF and the register to 0.
    await eventually(async () => (await p.get('co', 0, 4)).join() === '0,0,0,0' && (await p.get('hr', 0, 1))[0] === 0, 20_000, 'outputs OFF while slow');
    const acked = await observed.waitFor((m): m is Status => m.t === 'status' && !m.armed && m.devices[0]?.outputs === 'safe', 20_000, from);
    expect(acked.disarm?.cause).toBe(what === 'STOP' ? 'stop' : what === 'a watchdog trip' ? 'watchdog' : 'controller-lost');
    // The device is still slow: it was never made fast to let the safe write through.
    const writes = readWriteLog(writeLog).filter((w) => w.at >= since);
    const lastCoils = [...writes].reverse().find((w) => w.table === 'co');
    const lastRegister = [...writes].reverse().find((w) => w.table === 'hr');
    expect(lastCoils?.values).toEqual([0, 0, 0, 0]);
    expect(lastRegister?.values).toEqual([0]);
    // Status said the safe state was pending, and for how long, before it was acknowledged.
    const pending = c.messages
      .slice(mark)
      .concat(o.messages)
      .filter((m): m is Status => m.t === 'status' && m.devices[0]?.outputs === 'safe-pending');
    expect(pending.length).toBeGreaterThan(0);
    expect(lines.join('\n')).toMatch(/device "plant": safe state acknowledged after \d+\.\d s/);
    // Nothing but the safe image was written after the trigger was handled (no ON write slipped in later).
    const afterFirstSafe = writes.slice(writes.findIndex((w) => w.values.every((v) => v === 0)));
    expect(afterFirstSafe.filter((w) => w.values.some((v) => v !== 0))).toEqual([]);
    o.close();
  });

  it('says "safe state pending for N s" while the device has not answered yet', async () => {
    const { c, plant: p } = await rig();
    await p.mode('slow', 3000);
    const mark = c.messages.length;
    c.send({ t: 'stop', seq: 2 });
    const s = await c.waitFor((m): m is Status => m.t === 'status' && (m.devices[0]?.safePendingMs ?? 0) >= 1000, 10_000, mark);
    expect(s.devices[0]?.outputs).toBe('safe-pending');
    expect(s.devices[0]?.error).toMatch(/timed out/);
    await c.waitFor((m) => m.t === 'status' && m.devices[0]?.outputs === 'safe', 20_000, mark);
    expect(await p.get('co', 0, 4)).toEqual([0, 0, 0, 0]);
  });
});
