// `--plant`: the page (the gateway's controller) and an external Modbus master both writing the
// machine's actuators. Before, each overwrote the other silently. Now, as two masters on one real
// coupler are (otherMaster.test.ts): a Modbus write to an actuator while the controller drives them
// is refused (exception 06) and the gateway disarms, naming the point and the master; the safe image
// is written; the master may then drive the machine alone, and the controller's arm waits until it
// has stopped. The device's coils are read independently with mbpoll; pymodbus plays the master.
import { spawn } from 'node:child_process';
import { connect, type Socket } from 'node:net';
import { afterEach, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { PLANT_MASTER_QUIET_MS } from '../../src/gateway/simulatedDevice';
import type { GatewayMessage } from '../../src/protocol/messages';
import { eventually, mbpoll, mbpollValues, TestClient } from './helpers';

type Status = Extract<GatewayMessage, { t: 'status' }>;

/** Runs a pymodbus script (its port is argv[1]) to its end. */
function python(lines: readonly string[], port: number): Promise<{ code: number | null; out: string }> {
  const script = [
    'import sys',
    'from pymodbus.client import ModbusTcpClient',
    'c = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))',
    'assert c.connect()',
    'print("peer", c.socket.getsockname()[1], flush=True)',
    ...lines,
    'c.close()',
  ].join('\n');
  return new Promise((resolve) => {
    const p = spawn('/usr/bin/python3', ['-c', script, String(port)], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    p.stdout.on('data', (d: Buffer) => (out += d.toString()));
    p.stderr.on('data', (d: Buffer) => (out += d.toString()));
    // Never left hanging: a script that does not end within 20 s is killed (and its output says so).
    const timer = setTimeout(() => p.kill(), 20_000);
    p.on('close', (code) => {
      clearTimeout(timer);
      resolve({ code, out });
    });
  });
}

describe('--plant: the page and another Modbus master on the machine', () => {
  let gw: RunningGateway | undefined;
  const clients: TestClient[] = [];
  const sockets: Socket[] = [];
  const feeders: NodeJS.Timeout[] = [];
  afterEach(async () => {
    feeders.splice(0).forEach((t) => clearInterval(t));
    clients.splice(0).forEach((c) => c.close());
    sockets.splice(0).forEach((s) => s.destroy());
    await gw?.close();
    gw = undefined;
  });

  async function tankGateway(log: string[] = []) {
    // The device's own watchdog off: what the master's connection does is tested alone.
    const config = resolveConfig({ simulated: { modbusPort: 0, plant: 'tank', masterWatchdogMs: 0 } });
    gw = await startGateway({ port: 0, config, distDir: null, log: (l) => log.push(l) });
    return { gw, port: gw.simulated!.modbusServerPort! };
  }
  const pump = async (port: number) =>
    mbpollValues(await mbpoll(port, ['-t', '0', '-r', '0', '-c', '1', '127.0.0.1']))[0];

  /** The page drives the Pump ON, as it does every scan (the gateway's lease watchdog is fed). */
  function drivePump(c: TestClient): void {
    feeders.splice(0).forEach((t) => clearInterval(t));
    let seq = 0;
    const send = () => c.send({ t: 'outputs', seq: ++seq, values: { '%QX0.0': true } });
    send();
    feeders.push(setInterval(send, 100));
  }
  it('a master writing the Pump while the page drives it: refused, the gateway disarms naming Pump (%QX0.0) and the master, the pump is OFF; the master may then drive it alone, and arm waits until it stops', async () => {
    const log: string[] = [];
    const { gw, port } = await tankGateway(log);
    const c = await TestClient.armedController(gw.port, gw.token);
    clients.push(c);
    drivePump(c);
    await eventually(async () => (await pump(port)) === 1, 10_000, 'the page drives the Pump ON');

    const from = c.messages.length;
    const run = await python(
      [
        'r = c.write_coil(0, False)',
        'print("first", r.isError(), getattr(r, "exception_code", None), flush=True)',
        'print("after", c.read_coils(0, count=1).bits[0], flush=True)',
        // The gateway is off the actuators now: this master drives the machine alone.
        'r = c.write_coil(0, True)',
        'print("second", r.isError(), c.read_coils(0, count=1).bits[0], flush=True)',
      ],
      port,
    );
    expect(run.code, run.out).toBe(0);
    const peer = /^peer (\d+)$/m.exec(run.out)?.[1];
    expect(peer).toBeDefined();
    expect(run.out).toContain('first True 6'); // refused: server device busy
    expect(run.out).toContain('after False'); // the safe image, written as the gateway disarmed
    expect(run.out).toContain('second False True');

    const text = `another Modbus master (127.0.0.1:${peer}) wrote the machine "tank"'s Pump (%QX0.0) OFF while this gateway's controller drives it (ON); the write was refused`;
    const disarmed = (await c.waitFor(
      (m) => m.t === 'status' && !m.armed && m.disarm?.cause === 'other-master',
      5000,
      from,
    )) as Status;
    expect(disarmed.disarm?.message).toBe(
      `${text}: disarmed. This gateway switched off the outputs it still drove there and stops writing that device's outputs, so the two masters do not fight; stop the other master, then arm`,
    );
    expect(c.lastStatus()?.devices[0]?.conflict).toBe(text);
    expect(log).toContain(`machine "tank": ${text}`);
    // The master has gone: what it wrote falls OFF (read independently).
    await eventually(
      async () => (await pump(port)) === 0,
      10_000,
      'the Pump OFF after the master disconnected',
    );

    // A PLC writing the Pump every cycle has the machine now: arming would fight it, and is refused.
    const plc = spawn('/usr/bin/python3', [
      '-c',
      'import sys, time\nfrom pymodbus.client import ModbusTcpClient\nc = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))\nassert c.connect()\nprint("peer", c.socket.getsockname()[1], flush=True)\nwhile True:\n    c.write_coil(0, True)\n    time.sleep(0.1)',
      String(port),
    ]);
    try {
      let plcOut = '';
      plc.stdout.on('data', (d: Buffer) => (plcOut += d.toString()));
      await eventually(
        async () => /^peer \d+$/m.test(plcOut) && (await pump(port)) === 1,
        10_000,
        'the PLC drives the Pump',
      );
      const plcPeer = /^peer (\d+)$/m.exec(plcOut)![1];
      const before = c.messages.length;
      c.send({ t: 'arm' });
      const refused = await c.waitFor((m) => m.t === 'error' && m.code === 'arm-refused', 5000, before);
      expect(refused.t === 'error' && refused.message).toMatch(
        new RegExp(
          `^another Modbus master \\(127\\.0\\.0\\.1:${plcPeer}\\) is writing the machine "tank"'s actuators \\(Pump \\(%QX0\\.0\\) \\d+\\.\\d s ago\\): stop it, then arm; outputs stay in the safe state$`,
        ),
      );
      expect(gw.hub.status().armed).toBe(false);
    } finally {
      plc.kill();
    }
    await eventually(async () => (await pump(port)) === 0, 10_000, 'the Pump OFF after the PLC went');

    // Quiet for long enough: the operator arms, the page drives the machine again, the conflict is gone.
    await new Promise((r) => setTimeout(r, PLANT_MASTER_QUIET_MS));
    await c.arm();
    drivePump(c);
    await eventually(async () => (await pump(port)) === 1, 10_000, 'the page drives the Pump again');
    await eventually(() => c.lastStatus()?.devices[0]?.conflict === null, 5000, 'the conflict cleared');
  }, 120_000);

  it('a multiple-coil write (FC15) over the Pump the page drives is refused whole: the InletValve in it is not written either', async () => {
    const { gw, port } = await tankGateway();
    const c = await TestClient.armedController(gw.port, gw.token);
    clients.push(c);
    drivePump(c);
    await eventually(async () => (await pump(port)) === 1, 10_000, 'the page drives the Pump ON');
    const run = await python(
      [
        'r = c.write_coils(0, [False, True, True])',
        'print("fc15", r.isError(), c.read_coils(0, count=3).bits[:3], flush=True)',
      ],
      port,
    );
    expect(run.out).toContain('fc15 True [False, False, False]');
    expect(gw.hub.status().disarm?.cause).toBe('other-master');
    expect(mbpollValues(await mbpoll(port, ['-t', '0', '-r', '0', '-c', '3', '127.0.0.1']))).toEqual([
      0, 0, 0,
    ]);
  }, 90_000);

  it('a page connected as controller but not driving (disarmed) leaves the machine to the Modbus master: its writes are taken, no conflict', async () => {
    const { gw, port } = await tankGateway();
    const c = await TestClient.hello(gw.port, gw.token, 'controller');
    clients.push(c);
    const hmi = await new Promise<Socket>((resolve) => {
      const s = connect(port, '127.0.0.1', () => resolve(s));
    });
    sockets.push(hmi); // keeps a connection open: the master's outputs stay after it closes
    const run = await python(['print("write", c.write_coil(0, True).isError(), flush=True)'], port);
    expect(run.out).toContain('write False');
    expect(await pump(port)).toBe(1);
    expect(gw.hub.status().disarm?.cause).not.toBe('other-master');
    expect(gw.simulated!.conflict()).toBeNull();
  }, 90_000);

  it("what a master wrote before the page armed is not dropped over the page's outputs when that master's connection closes", async () => {
    const log: string[] = [];
    const { gw, port } = await tankGateway(log);
    const hmi = await new Promise<Socket>((resolve) => {
      const s = connect(port, '127.0.0.1', () => resolve(s));
    });
    sockets.push(hmi);
    const run = await python(['print("write", c.write_coil(0, True).isError(), flush=True)'], port);
    expect(run.out).toContain('write False');
    await new Promise((r) => setTimeout(r, PLANT_MASTER_QUIET_MS));
    const c = await TestClient.armedController(gw.port, gw.token);
    clients.push(c);
    drivePump(c);
    await eventually(async () => (await pump(port)) === 1, 10_000, 'the page drives the Pump');
    hmi.destroy(); // the last Modbus client goes (mbpoll's own connections close too)
    for (let i = 0; i < 10; i++) {
      await new Promise((r) => setTimeout(r, 50));
      expect(await pump(port)).toBe(1);
    }
    expect(log.filter((l) => l.includes('the outputs it wrote are OFF'))).toEqual([]);
    expect(gw.hub.status().armed).toBe(true);
  }, 90_000);
});
