// Virtual commissioning (issue 26): `npm start -- --plant tank` makes the gateway's simulated
// Modbus device be the tank, advancing in real time. pymodbus plays the PLC: it writes the pump
// and valve coils and reads the level back rising, then falling.
import { spawn } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { connect } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterEach, expect, test, vi } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway } from '../../src/gateway/gateway';
import { SimulatedDevice, simulatedDeviceMisfit } from '../../src/gateway/simulatedDevice';
import { PLANTS } from '../../src/plant/machines';
import { eventually, mbpoll, mbpollValues, TestClient } from './helpers';

const MASTER = fileURLToPath(new URL('./fixtures/plant_master.py', import.meta.url));
let device: SimulatedDevice | undefined;
afterEach(async () => {
  await device?.close();
  device = undefined;
});

test('pymodbus as the PLC fills the tank and drains it through the --plant tank device', async () => {
  device = new SimulatedDevice(0, 'tank');
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  const port = device.modbusServerPort!;
  const run = await new Promise<{ code: number | null; out: string }>((resolve) => {
    const p = spawn('/usr/bin/python3', [MASTER, String(port)], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    p.stdout.on('data', (d: Buffer) => (out += d.toString()));
    p.stderr.on('data', (d: Buffer) => (out += d.toString()));
    p.on('close', (code) => resolve({ code, out }));
  });
  expect(run.code, run.out).toBe(0);
  const levels = run.out.split('\n').flatMap((l) => {
    const m = /^level (\d+)$/.exec(l);
    return m ? [Number(m[1])] : [];
  });
  const peak = Math.max(...levels);
  expect(peak).toBeGreaterThanOrEqual(levels[0]! + 30);
  expect(levels.at(-1)!).toBeLessThanOrEqual(peak - 30);
  expect(device.plantRead('tank.spilled')).toBe(0);
}, 90_000);

test('without --plant the simulated device is no machine', async () => {
  device = new SimulatedDevice(0);
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  expect(device.plantRead('level')).toBeUndefined();
});

test('a Modbus write over one of the machine\'s sensors is refused (the sensor would stay so); an operator control may be pressed', async () => {
  device = new SimulatedDevice(0, 'tank');
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  const port = device.modbusServerPort!;
  // Coil 800 + n sets discrete input n, holding register 2048 + n input register n: %IX0.0 is the
  // tank's Start button, %IX0.2 its low level switch (OFF at 100 L), %IW0 its level transmitter.
  const script = [
    'import sys',
    'from pymodbus.client import ModbusTcpClient',
    'c = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))',
    'assert c.connect()',
    'low = c.write_coil(802, True)',
    'level = c.write_register(2048, 999)',
    'start = c.write_coil(800, True)',
    'print("low", low.isError(), "level", level.isError(), "start", start.isError())',
    'print("inputs", c.read_discrete_inputs(0, count=3).bits[:3], c.read_input_registers(0, count=1).registers[0])',
    'c.close()',
  ].join('\n');
  const run = await new Promise<{ code: number | null; out: string }>((resolve) => {
    const p = spawn('/usr/bin/python3', ['-c', script, String(port)], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    p.stdout.on('data', (d: Buffer) => (out += d.toString()));
    p.stderr.on('data', (d: Buffer) => (out += d.toString()));
    p.on('close', (code) => resolve({ code, out }));
  });
  expect(run.code, run.out).toBe(0);
  expect(run.out).toContain('low True level True start False');
  // The low switch is still OFF (100 L), the level is the machine's, Start is held.
  expect(run.out).toMatch(/inputs \[True, False, False\] 10\d\b/);
  expect(device.plantRead('tank.LowLevel')).toBe(false);
}, 60_000);

/** Runs a pymodbus script (its port is argv[1]) to its end. */
function python(script: string, port: number): Promise<{ code: number | null; out: string }> {
  return new Promise((resolve) => {
    const p = spawn('/usr/bin/python3', ['-c', script, String(port)], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    p.stdout.on('data', (d: Buffer) => (out += d.toString()));
    p.stderr.on('data', (d: Buffer) => (out += d.toString()));
    p.on('close', (code) => resolve({ code, out }));
  });
}

/** Waits (generously) for `cond`, polling the device: the machine steps in real time. */
async function until(cond: () => boolean, what: string): Promise<void> {
  const end = Date.now() + 30_000;
  while (!cond()) {
    if (Date.now() > end) throw new Error(`timed out waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 20));
  }
}

test('the PLC gone (its Modbus connection closed), the outputs it wrote fall OFF: the pump stops, the tank does not overflow', async () => {
  const log: string[] = [];
  // The device watchdog off: this master writes once, and the connection's closing alone is tested.
  device = new SimulatedDevice(0, 'tank', (line) => log.push(line), 0);
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  const port = device.modbusServerPort!;
  const master = [
    'import sys',
    'from pymodbus.client import ModbusTcpClient',
    'c = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))',
    'assert c.connect()',
    'assert not c.write_coils(0, [True, True]).isError()',
    'print("coils", c.read_coils(0, count=2).bits[:2], flush=True)',
    // %QW0, where a machine's INT actuator (a speed setpoint) would be: the master's too.
    'assert not c.write_register(0, 1234).isError()',
    'c.close()',
  ].join('\n');
  // An HMI (or a second PLC) still connected keeps them: the outputs fall when the last master goes.
  const hmi = await new Promise<import('node:net').Socket>((resolve) => {
    const s = connect(port, '127.0.0.1', () => resolve(s));
  });
  const run = await python(master, port);
  expect(run.code, run.out).toBe(0);
  expect(run.out).toContain('coils [True, True]');
  await until(() => device!.plantRead('tank.inflow') !== 0, 'the pump to deliver water');
  await new Promise((r) => setTimeout(r, 200));
  expect(device.writtenValues().get('%QX0.0')).toBe(true);
  expect(device.writtenValues().get('%QW0')).toBe(1234);
  hmi.destroy();
  await until(() => device!.writtenValues().get('%QX0.0') === false, 'the pump coil to fall OFF');
  expect(device.writtenValues().get('%QX0.1')).toBe(false);
  expect(device.writtenValues().get('%QW0')).toBe(0);
  expect(log).toEqual(['machine "tank": the Modbus master (the PLC) disconnected; the outputs it wrote are OFF (Pump, InletValve)']);
  expect(device.plantRead('tank.Pump')).toBe(false);
  await until(() => device!.plantRead('tank.inflow') === 0, 'the pump to run down and the inlet to close');
  // A PLC that reconnects finds its outputs OFF and drives them again.
  const again = await python(
    [
      'import sys',
      'from pymodbus.client import ModbusTcpClient',
      'c = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))',
      'assert c.connect()',
      'print("coils", c.read_coils(0, count=2).bits[:2])',
      'c.close()',
    ].join('\n'),
    port,
  );
  expect(again.out).toContain('coils [False, False]');
  expect(device.plantRead('tank.overflows')).toBe(0);
}, 90_000);

/** `rungsmith-gateway ARGS` run to its exit (a refused start exits at once). */
function gateway(args: readonly string[]): Promise<{ code: number | null; err: string }> {
  return new Promise((resolve) => {
    const p = spawn(process.execPath, ['bin/rungsmith-gateway.mjs', '--port', '0', '--no-app', ...args], { stdio: ['ignore', 'ignore', 'pipe'] });
    let err = '';
    p.stderr.on('data', (d: Buffer) => (err += d.toString()));
    const kill = setTimeout(() => p.kill('SIGTERM'), 30_000);
    p.on('close', (code) => {
      clearTimeout(kill);
      resolve({ code, err });
    });
  });
}

test('--plant with a wrong name, or with --config naming real devices (no simulated device to be the machine), is refused at start', async () => {
  const wrong = await gateway(['--sim-port', '0', '--plant', 'tnak']);
  expect(wrong.code).toBe(2);
  expect(wrong.err).toContain('--plant: there is no machine "tnak"; the machines are tank, lift, garage, mixer, boxes, intersection');
  const dir = mkdtempSync(join(tmpdir(), 'rungsmith-plant-'));
  const config = join(dir, 'gateway.json');
  writeFileSync(config, JSON.stringify({ devices: [{ id: 'io1', host: '127.0.0.1', port: 1, points: [{ address: '%IX0.0' }] }] }));
  const withDevices = await gateway(['--config', config, '--plant', 'tank']);
  expect(withDevices.code).toBe(2);
  expect(withDevices.err).toContain(`--plant (with --config ${config}): the machine "tank" is the built-in simulated device, which runs only with no "devices" configured`);
}, 60_000);

test("the Hardware panel cannot set the machine's sensors either (they would stay so); its operator controls it can", async () => {
  const gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: null, plant: 'tank' } }), distDir: null });
  try {
    const c = await TestClient.hello(gw.port, gw.token, 'observer');
    // %IX0.3 is the high level switch: OFF at 100 L. %IX0.0 the Start button.
    c.send({ t: 'simulate', seq: 1, values: { '%IX0.3': true } });
    await eventually(() => c.messages.some((m) => m.t === 'error'), 5000, 'the refusal');
    expect(c.messages.find((m) => m.t === 'error')).toMatchObject({
      code: 'not-input',
      message: '%IX0.3 is the machine "tank"\'s sensor HighLevel: the machine sets it',
      ref: 1,
    });
    c.send({ t: 'simulate', seq: 2, values: { '%IX0.0': true } });
    await eventually(() => c.values()['%IX0.0'] === true, 5000, 'Start held');
    expect(gw.simulated!.inputValues().get('%IX0.3')).toBe(false);
    expect(gw.simulated!.plantRead('tank.HighLevel')).toBe(false);
    c.close();
  } finally {
    await gw.close();
  }
}, 60_000);

test('every machine fits the simulated device; a machine with a point beyond it (a new one, docs/PLANTS.md) is refused at start, named', () => {
  for (const model of PLANTS) expect(simulatedDeviceMisfit(model), model.id).toBeUndefined();
  const oven = {
    id: 'oven',
    points: [
      { name: 'Heater', address: '%QX0.0', type: 'BOOL', kind: 'actuator', comment: 'Heater contactor' },
      { name: 'Hot', address: '%IX2.1', type: 'BOOL', kind: 'sensor', comment: 'Thermostat' },
    ],
  } as const;
  expect(simulatedDeviceMisfit(oven)).toBe(
    'the machine "oven"\'s sensor Hot at %IX2.1 has no place on the simulated device (%IX0.0-%IX1.7, %QX0.0-%QX1.7, %IW0-%IW3, %QW0-%QW3)',
  );
});

test('the wall clock stepped (NTP, the user setting it) does not leap the machine: a filling tank does not overflow in one step', async () => {
  device = new SimulatedDevice(null, 'tank');
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  device.drive(new Map([['%QX0.0', true], ['%QX0.1', true]]));
  await until(() => (device!.plantRead('tank.inflow') as number) > 0, 'the pump to deliver water');
  const real = Date.now.bind(Date);
  // The wall clock jumps an hour ahead, then back two hours: the machine's time is real time elapsed.
  const spy = vi.spyOn(Date, 'now').mockImplementation(() => real() + 3_600_000);
  try {
    await new Promise((r) => setTimeout(r, 300));
    spy.mockImplementation(() => real() - 3_600_000);
    const levels: number[] = [];
    const end = real() + 300;
    while (real() < end) {
      levels.push(device.plantRead('tank.level') as number);
      await new Promise((r) => setTimeout(r, 20));
    }
    for (let i = 1; i < levels.length; i++) expect(levels[i]!).toBeGreaterThanOrEqual(levels[i - 1]!);
    expect(levels.at(-1)!).toBeGreaterThan(levels[0]!);
    // 25 L/s for well under a minute from 100 L: nowhere near the rim.
    expect(device.plantRead('tank.level') as number).toBeLessThan(600);
    expect(device.plantRead('tank.overflows')).toBe(0);
  } finally {
    spy.mockRestore();
  }
}, 60_000);

test("the machine's consequences go to the gateway's log, in real time: both door contactors on shorts the garage's motor", async () => {
  const log: string[] = [];
  device = new SimulatedDevice(null, 'garage', (line) => log.push(line));
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  device.drive(new Map([['%QX0.0', true], ['%QX0.1', true]]));
  await until(() => log.length > 0, 'the consequence in the log');
  expect(log[0]).toMatch(/^machine "garage": error MotorUp and MotorDown were on together \(short circuit\), \d+\.\d s after the gateway started$/);
  expect(device.plantRead('garage.shorts')).toBe(1);
}, 60_000);

test("an operator control set over Modbus or from the Hardware panel operates the machine: the garage's Doorway drives a car in, its photo-eye sees it", async () => {
  const gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: 0, plant: 'garage' } }), distDir: null });
  try {
    const sim = gw.simulated!;
    // The door opened past the car's roof (12 s end to end; a car cannot drive through a closed door).
    sim.drive(new Map([['%QX0.0', true]]));
    await until(() => (sim.plantRead('garage.position') as number) > 70, 'the door open past the car');
    sim.drive(new Map([['%QX0.0', false]]));
    // Coil 806 sets %IX0.6, the garage's Doorway switch: a car drives into the doorway.
    const run = await python(
      [
        'import sys',
        'from pymodbus.client import ModbusTcpClient',
        'c = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))',
        'assert c.connect()',
        'assert not c.write_coil(806, True).isError()',
        'c.close()',
      ].join('\n'),
      sim.modbusServerPort!,
    );
    expect(run.code, run.out).toBe(0);
    await until(() => sim.plantRead('garage.car_in') === true, 'the car in the doorway');
    // %IX0.5, the photo-eye across the doorway, sees it.
    await until(() => sim.inputValues().get('%IX0.5') === true, 'the photo-eye broken');
    // The Hardware panel drives it out again.
    const c = await TestClient.hello(gw.port, gw.token, 'observer');
    c.send({ t: 'simulate', seq: 1, values: { '%IX0.6': false } });
    await until(() => sim.plantRead('garage.car_in') === false, 'the car gone');
    await until(() => sim.inputValues().get('%IX0.5') === false, 'the photo-eye clear');
    c.close();
  } finally {
    await gw.close();
  }
}, 60_000);

test('a PLC that stays connected but stops writing (hung; an HMI keeps its own connection open) loses its outputs after the device watchdog, 1000 ms by default, as an I/O coupler does; one that rewrites them every cycle keeps them', async () => {
  const log: string[] = [];
  device = new SimulatedDevice(0, 'tank', (line) => log.push(line));
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  const port = device.modbusServerPort!;
  // An HMI connected all along: it reads, it never writes the outputs.
  const hmi = await new Promise<import('node:net').Socket>((resolve) => {
    const s = connect(port, '127.0.0.1', () => resolve(s));
  });
  try {
    // The PLC writes pump and inlet every 200 ms (its cycle) for 3 s, then hangs: connected, reading, writing nothing.
    const run = await python(
      [
        'import sys, time',
        'from pymodbus.client import ModbusTcpClient',
        'c = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))',
        'assert c.connect()',
        'end = time.time() + 3',
        'while time.time() < end:',
        '    assert not c.write_coils(0, [True, True]).isError()',
        '    time.sleep(0.2)',
        '    print("cycling", c.read_coils(0, count=2).bits[:2], flush=True)',
        'end = time.time() + 20',
        'while time.time() < end:',
        '    bits = c.read_coils(0, count=2).bits[:2]',
        '    if bits == [False, False]:',
        '        print("hung: off", flush=True)',
        '        break',
        '    time.sleep(0.05)',
        'c.close()',
      ].join('\n'),
      port,
    );
    expect(run.code, run.out).toBe(0);
    const cycling = run.out.split('\n').filter((l) => l.startsWith('cycling'));
    expect(cycling.length).toBeGreaterThan(5);
    // Rewritten every cycle, the outputs never dropped (3 s, three times the watchdog).
    expect(cycling.every((l) => l === 'cycling [True, True]'), run.out).toBe(true);
    expect(run.out).toContain('hung: off');
    expect(log[0]).toBe(
      'machine "tank": no write to its outputs from the Modbus master (the PLC) for 1000 ms (the device\'s communication watchdog, as an I/O coupler\'s; a PLC rewrites its outputs every cycle); the outputs it wrote are OFF (Pump, InletValve)',
    );
    expect(device.plantRead('tank.Pump')).toBe(false);
    // Read independently, with mbpoll, while the HMI is still connected.
    expect(mbpollValues(await mbpoll(port, ['-t', '0', '-r', '0', '-c', '2', '127.0.0.1']))).toEqual([0, 0]);
  } finally {
    hmi.destroy();
  }
}, 90_000);

test('--plant-watchdog 0 turns the device watchdog off (a master writing once keeps its outputs while connected); a bad value is refused at start', async () => {
  device = new SimulatedDevice(0, 'tank', () => undefined, 0);
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  const run = await python(
    [
      'import sys, time',
      'from pymodbus.client import ModbusTcpClient',
      'c = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))',
      'assert c.connect()',
      'assert not c.write_coil(0, True).isError()',
      'time.sleep(2.5)',
      'print("after", c.read_coils(0, count=1).bits[0], flush=True)',
      'c.close()',
    ].join('\n'),
    device.modbusServerPort!,
  );
  expect(run.out).toContain('after True');
  const bad = await gateway(['--sim-port', '0', '--plant', 'tank', '--plant-watchdog', '50']);
  expect(bad.code).toBe(2);
  expect(bad.err).toContain('--plant-watchdog: needs 0 (off) or 100 to 60000 ms, got "50"');
}, 60_000);

test("a push button held over Modbus (an HMI, a test script) springs back when the last Modbus client disconnects", async () => {
  const log: string[] = [];
  device = new SimulatedDevice(0, 'garage', (line) => log.push(line));
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  const port = device.modbusServerPort!;
  // Coil 800 + n sets discrete input n: %IX0.0 the garage's KeyOpen push button, pressed and never
  // released by a script that ends (or an HMI that crashes) while holding it.
  const run = await python(
    [
      'import sys',
      'from pymodbus.client import ModbusTcpClient',
      'c = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))',
      'assert c.connect()',
      'assert not c.write_coil(800, True).isError()',
      'print("held", c.read_discrete_inputs(0, count=1).bits[0], flush=True)',
      'c.close()',
    ].join('\n'),
    port,
  );
  expect(run.out).toContain('held True');
  await until(() => device!.inputValues().get('%IX0.0') === false, 'KeyOpen released');
  expect(mbpollValues(await mbpoll(port, ['-t', '1', '-r', '0', '-c', '1', '127.0.0.1']))).toEqual([0]);
  expect(device.plantRead('garage.KeyOpen')).toBe(false);
  expect(log).toContain('machine "garage": the last Modbus client disconnected holding KeyOpen; released (a push button springs back)');
}, 60_000);
