// The real command: SIGTERM writes the safe state to the device before the process exits.
import { spawn } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createInterface } from 'node:readline';
import { afterAll, describe, expect, it } from 'vitest';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { eventually, PyModbusServer, TestClient } from './helpers';

describe('rungsmith-gateway process', () => {
  let plant: PyModbusServer | undefined;
  afterAll(() => plant?.kill());

  it('prints the URL with the token, and leaves every output at 0 on SIGTERM', async () => {
    const modbusPort = await freeLoopbackPort();
    plant = await PyModbusServer.start(modbusPort);
    const dir = mkdtempSync(join(tmpdir(), 'rungsmith-gw-'));
    const config = join(dir, 'gateway.json');
    writeFileSync(
      config,
      JSON.stringify({
        watchdogMs: 5000,
        devices: [{ id: 'plant', host: '127.0.0.1', port: modbusPort, pollMs: 50, points: [{ address: '%QX0.0', count: 4 }, { address: '%QW0' }] }],
      }),
    );
    const proc = spawn(process.execPath, ['bin/rungsmith-gateway.mjs', '--port', '0', '--config', config, '--no-app'], { stdio: ['ignore', 'pipe', 'pipe'] });
    proc.stderr.resume();
    const line = await new Promise<string>((resolve) => createInterface({ input: proc.stdout }).once('line', resolve));
    const m = /open (http:\/\/127\.0\.0\.1:(\d+)\/#token=(\S+))$/.exec(line);
    expect(m).not.toBeNull();
    const [port, token] = [Number(m?.[2]), m?.[3] ?? ''];

    const c = await TestClient.armedController(port, token);
    c.send({ t: 'outputs', seq: 1, values: { '%QX0.0': true, '%QX0.2': true, '%QW0': 99 } });
    await eventually(async () => (await plant!.get('co', 0, 4)).join() === '1,0,1,0', 5000, 'coils on');
    const exited = new Promise<number | null>((resolve) => proc.once('exit', (code) => resolve(code)));
    proc.kill('SIGTERM');
    expect(await exited).toBe(0);
    expect(await plant.get('co', 0, 4)).toEqual([0, 0, 0, 0]);
    expect(await plant.get('hr', 0, 1)).toEqual([0]);
  });
});
