// Virtual commissioning (issue 26): `npm start -- --plant tank` makes the gateway's simulated
// Modbus device be the tank, advancing in real time. pymodbus plays the PLC: it writes the pump
// and valve coils and reads the level back rising, then falling.
import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { afterEach, expect, test } from 'vitest';
import { SimulatedDevice } from '../../src/gateway/simulatedDevice';

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
