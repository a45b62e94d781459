// Issue 21.1: every catchable way to end the gateway process writes the safe image as the last write
// to the device: a closed terminal or dropped SSH session (SIGHUP, with stdout/stderr now broken
// pipes), Ctrl+\ (SIGQUIT), Ctrl+C (SIGINT), kill (SIGTERM). Against Debian's pymodbus server.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { eventually, PyModbusServer, readWriteLog, spawnGateway, TestClient } from './helpers';

describe('the gateway process ends with the safe image on every catchable signal', () => {
  let plant: PyModbusServer;
  let modbusPort = 0;
  const dir = mkdtempSync(join(tmpdir(), 'rungsmith-signals-'));
  const writeLog = join(dir, 'writes.log');
  beforeAll(async () => {
    modbusPort = await freeLoopbackPort();
    plant = await PyModbusServer.start(modbusPort, writeLog);
  });
  afterAll(() => plant?.kill());

  it.each([
    ['SIGHUP', 'the terminal closed (stdin, stdout and stderr pipes closed first)', true],
    ['SIGQUIT', 'Ctrl+\\', false],
    ['SIGINT', 'Ctrl+C', false],
    ['SIGHUP', 'an SSH session dropped with the log still readable', false],
  ] as const)('%s (%s): the device reads all OFF and its last write is the safe image', async (signal, _what, closePipes) => {
    const config = join(dir, `gateway-${signal}-${String(closePipes)}.json`);
    writeFileSync(
      config,
      JSON.stringify({
        watchdogMs: 5000,
        devices: [{ id: 'plant', host: '127.0.0.1', port: modbusPort, pollMs: 50, points: [{ address: '%QX0.0', count: 4 }, { address: '%QW0' }] }],
      }),
    );
    const gw = await spawnGateway(config);
    const c = await TestClient.armedController(gw.port, gw.token);
    c.send({ t: 'outputs', seq: 1, values: { '%QX0.0': true, '%QX0.1': true, '%QX0.3': true, '%QW0': 1234 } });
    await eventually(async () => (await plant.get('co', 0, 4)).join() === '1,1,0,1' && (await plant.get('hr', 0, 1))[0] === 1234, 10_000, 'outputs ON');
    const from = Date.now();
    // Keep the program running until the very end, so the safe image has to be the last write.
    const scans = setInterval(() => c.send({ t: 'outputs', seq: 2, values: { '%QX0.0': true, '%QX0.1': true, '%QX0.3': true, '%QW0': 1234 } }), 10);
    if (closePipes) {
      gw.proc.stdin.destroy();
      gw.proc.stdout.destroy();
      gw.proc.stderr.destroy();
    }
    gw.proc.kill(signal);
    const exit = await gw.exited;
    clearInterval(scans);
    c.close();
    expect(exit).toEqual({ code: 0, signal: null });
    expect(await plant.get('co', 0, 4)).toEqual([0, 0, 0, 0]);
    expect(await plant.get('hr', 0, 1)).toEqual([0]);
    const writes = readWriteLog(writeLog);
    const lastCoils = [...writes].reverse().find((w) => w.table === 'co');
    const lastRegister = [...writes].reverse().find((w) => w.table === 'hr');
    expect(lastCoils?.values).toEqual([0, 0, 0, 0]);
    expect(lastRegister?.values).toEqual([0]);
    expect(lastCoils!.at).toBeGreaterThanOrEqual(from - 1000);
    if (!closePipes) expect(gw.stderr()).toContain(`${signal}: stopping, writing the safe state as the last write`);
    if (!closePipes) expect(gw.stderr()).toContain('device "plant": safe state written and acknowledged');
  });
});
