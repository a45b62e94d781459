// Forcing or writing a real output while the page drives hardware asks to confirm first (as TIA Portal
// warns before a force on a real output), whichever way the force is made: the canvas menu on the
// coil, the Watch row's Force and Write, F7 on a prepared value. The dialog names the output, its
// address, the device and the value; Cancel has the focus and sends nothing. In a real Chromium
// against the gateway serving the built app with its simulated device; the device's coil is read
// independently over Modbus TCP with mbpoll, never from the page.
import { spawn } from 'node:child_process';
import type { Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { eventually, mbpoll, mbpollValues, PyModbusServer } from '../gateway/helpers';
import { openApp, useChromium } from './appPage';
import { useHardwareGateway } from './hardwareLab';
import { SimPage } from './simPage';

const browser = useChromium();

/** Scans the page shows, to let some pass. */
const scan = async (page: Page) => Number(await page.getByTestId('sim-scan').textContent());
/** How many variables the simulator holds forced. */
const forcedCount = (page: Page) =>
  page.evaluate(() => (window.rungsmith!.simStore as { getState(): { forced: Map<string, unknown> } }).getState().forced.size);
async function scansPass(page: Page, n: number) {
  const from = await scan(page);
  await expect.poll(() => scan(page), { timeout: 30_000 }).toBeGreaterThan(from + n);
}

describe('forcing a real output asks to confirm', () => {
  const lab = useHardwareGateway(browser);
  const { coils, deviceInput, openOnHardware } = lab;

  /** The motor example running on the simulated device (Stop not closed: the program keeps Motor OFF). */
  async function motorOnHardware() {
    const opened = await openOnHardware('Motor start/stop (seal-in)');
    await opened.sim.button('run').click();
    await opened.sim.waitForMode('Running');
    await expect.poll(() => lab.gateway().hub.status().armed).toBe(true);
    return opened;
  }

  /** The confirmation for Motor to TRUE, with Cancel focused. */
  async function expectDialog(page: Page, verb: 'Force' | 'Write') {
    const dialog = page.getByTestId('hw-output-confirm');
    await expect.poll(() => dialog.count()).toBe(1);
    expect(await dialog.getByTestId('hw-output-confirm-title').textContent()).toBe(
      `${verb} real output Motor (%QX0.0) to TRUE?`,
    );
    expect(await dialog.textContent()).toContain(
      `Motor is output %QX0.0 of device "sim" (the gateway's simulated device).`,
    );
    expect(await dialog.textContent()).toContain('can cause injury or damage');
    expect(await page.evaluate(() => document.activeElement?.getAttribute('data-testid'))).toBe(
      'hw-output-cancel',
    );
    return dialog;
  }

  it('canvas menu on the Motor coil: Force TRUE asks; Cancel leaves the coil OFF on the device, Confirm drives it ON; unforced, the seal-in holds it until Stop on the device', async () => {
    const { page, errors, sim } = await motorOnHardware();
    const coil = await sim.draw.cellPoint(0, 0, 9);
    const forceTrue = async () => {
      await page.mouse.click(coil.x, coil.y, { button: 'right' });
      await page.getByTestId('sim-context-menu').getByRole('menuitem', { name: 'Force TRUE' }).click();
    };

    await forceTrue();
    const dialog = await expectDialog(page, 'Force');
    expect(await dialog.getByTestId('hw-output-confirm-when').textContent()).toBe(
      'The program drives the outputs: the device gets it at the next scan.',
    );
    await dialog.getByTestId('hw-output-cancel').click();
    await expect.poll(() => dialog.count()).toBe(0);
    await scansPass(page, 20);
    expect(await sim.value('Motor')).toBe(false);
    expect(await forcedCount(page)).toBe(0);
    expect((await coils())[0]).toBe(0);

    await forceTrue();
    await (await expectDialog(page, 'Force')).getByTestId('hw-output-ok').click();
    await eventually(async () => (await coils())[0] === 1, 10_000, 'Motor ON on the device after Confirm');
    expect(await sim.value('Motor')).toBe(true);

    // Unforcing asks nothing; the program's seal-in keeps the motor it found ON running (as a real
    // PLC would) until Stop is pressed on the device.
    await page.mouse.click(coil.x, coil.y, { button: 'right' });
    await page.getByTestId('sim-context-menu').getByRole('menuitem', { name: 'Unforce' }).click();
    await expect.poll(() => forcedCount(page)).toBe(0);
    expect((await coils())[0]).toBe(1);
    await deviceInput(1, true);
    await eventually(async () => (await coils())[0] === 0, 10_000, 'Motor OFF on the device after Stop');
    expect(errors).toEqual([]);
  });

  it('Watch row Force (Escape), Write (Cancel) and F7 on a prepared TRUE (Cancel) all ask, and none reaches the device', async () => {
    const { page, errors, sim } = await motorOnHardware();
    await sim.tab('Watch');
    await page.getByTestId('watch-add-name').fill('Motor');
    await page.getByTestId('watch-add').click();
    const row = page.getByTestId('watch-row-Motor');
    await row.getByTestId('watch-input').fill('TRUE');

    await row.getByTestId('watch-force').click();
    await expectDialog(page, 'Force');
    await page.keyboard.press('Escape');
    await expect.poll(() => page.getByTestId('hw-output-confirm').count()).toBe(0);

    await row.getByTestId('watch-write').click();
    const write = await expectDialog(page, 'Write');
    await write.getByTestId('hw-output-cancel').click();
    await expect.poll(() => page.getByTestId('hw-output-confirm').count()).toBe(0);

    await page.getByTestId('watch-panel').click({ position: { x: 5, y: 5 } });
    await page.keyboard.press('F7');
    const f7 = await expectDialog(page, 'Force');
    expect(await page.getByTestId('status-bar').textContent()).toMatch(
      /Motor \(%QX0\.0\): a real output, forced only when you confirm it\./,
    );
    await f7.getByTestId('hw-output-cancel').click();
    await expect.poll(() => page.getByTestId('hw-output-confirm').count()).toBe(0);

    await scansPass(page, 20);
    expect(await sim.value('Motor')).toBe(false);
    expect(await forcedCount(page)).toBe(0);
    for (let i = 0; i < 5; i++) expect((await coils())[0]).toBe(0);
    expect(errors).toEqual([]);
  });

  it('without hardware, forcing the Motor coil stays one click: no confirmation', async () => {
    const { page, errors } = await openApp(browser(), lab.gateway().url);
    lab.pages.push(page);
    const sim = new SimPage(page);
    await sim.runExample('Motor start/stop (seal-in)');
    const coil = await sim.draw.cellPoint(0, 0, 9);
    await page.mouse.click(coil.x, coil.y, { button: 'right' });
    await page.getByTestId('sim-context-menu').getByRole('menuitem', { name: 'Force TRUE' }).click();
    await sim.waitForValue('Motor', true);
    expect(await page.getByTestId('hw-output-confirm').count()).toBe(0);
    // The page drives no hardware: the device's coil stays OFF.
    expect((await coils())[0]).toBe(0);
    expect(errors).toEqual([]);
  });
});

describe('--plant: another Modbus master writes an actuator the page drives', () => {
  let gw: RunningGateway;
  const pages: Page[] = [];
  beforeAll(async () => {
    gw = await startGateway({
      port: 0,
      config: resolveConfig({ simulated: { modbusPort: 0, plant: 'tank', masterWatchdogMs: 0 } }),
      distDir: 'dist',
    });
  });
  afterAll(async () => {
    await gw?.close();
  });
  afterEach(async () => {
    for (const p of pages.splice(0)) await p.close().catch(() => undefined);
  });
  const port = () => gw.simulated!.modbusServerPort!;
  const pump = async () =>
    mbpollValues(await mbpoll(port(), ['-t', '0', '-r', '0', '-c', '1', '127.0.0.1']))[0];

  it('the Hardware panel names the point and the master, the write is refused and the Pump is OFF on the machine; a PLC writing it cyclically then has it, and Arm is refused while it does', async () => {
    const { page, errors } = await openApp(browser(), gw.url);
    pages.push(page);
    const sim = new SimPage(page);
    await sim.openExample('Motor start/stop (seal-in)'); // Motor at %QX0.0: the tank's Pump
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await expect.poll(() => gw.hub.status().armed).toBe(true);
    const coil = await sim.draw.cellPoint(0, 0, 9);
    await page.mouse.click(coil.x, coil.y, { button: 'right' });
    await page.getByTestId('sim-context-menu').getByRole('menuitem', { name: 'Force TRUE' }).click();
    await page.getByTestId('hw-output-ok').click();
    await eventually(async () => (await pump()) === 1, 10_000, 'the page drives the Pump ON');

    // mbpoll as the other master switches the Pump off: refused (exception 06), mbpoll says so.
    const refused = await mbpoll(port(), ['-t', '0', '-r', '0', '127.0.0.1', '0']).then(
      () => 'written',
      (e: Error) => e.message,
    );
    expect(refused).toMatch(/busy/i);
    const text =
      /^another Modbus master \(127\.0\.0\.1:\d+\) wrote the machine "tank"'s Pump \(%QX0\.0\) OFF while this gateway's controller drives it \(ON\); the write was refused/;
    await expect
      .poll(() => panel.getByTestId('hw-disarm').textContent(), { timeout: 10_000 })
      .toMatch(
        /another Modbus master \(127\.0\.0\.1:\d+\) wrote the machine "tank"'s Pump \(%QX0\.0\) OFF .*: disarmed/,
      );
    const row =
      (await panel.getByTestId('hw-device-sim').getByTestId('hw-device-outputs').textContent()) ?? '';
    expect(row.replace(/^not written by this gateway: /, '')).toMatch(text);
    // The safe image is on the machine (read independently), while the program still forces Motor.
    expect(await pump()).toBe(0);
    expect(await sim.value('Motor')).toBe(true);

    // A PLC keeps writing the Pump every 100 ms: the machine is its now, and Arm is refused while it does.
    const plc = spawn('/usr/bin/python3', [
      '-c',
      'import sys, time\nfrom pymodbus.client import ModbusTcpClient\nc = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]))\nassert c.connect()\nwhile True:\n    c.write_coil(0, True)\n    time.sleep(0.1)',
      String(port()),
    ]);
    try {
      await eventually(async () => (await pump()) === 1, 10_000, 'the PLC drives the Pump');
      await panel.getByTestId('hw-arm').click();
      await expect
        .poll(() => panel.getByTestId('hw-last-error').textContent(), { timeout: 10_000 })
        .toMatch(
          /^Arm refused: another Modbus master \(127\.0\.0\.1:\d+\) is writing the machine "tank"'s actuators \(Pump \(%QX0\.0\) \d+\.\d s ago\): stop it, then arm/,
        );
      expect(gw.hub.status().armed).toBe(false);
    } finally {
      plc.kill();
    }
    // The PLC gone, what it wrote falls OFF (its connection closed).
    await eventually(async () => (await pump()) === 0, 10_000, 'the Pump OFF after the PLC went');
    expect(errors).toEqual([]);
  });
});

describe('forcing a real output of a Modbus TCP device (pymodbus) asks to confirm', () => {
  let plant: PyModbusServer;
  let gw: RunningGateway;
  const pages: Page[] = [];
  beforeAll(async () => {
    const modbusPort = await freeLoopbackPort();
    plant = await PyModbusServer.start(modbusPort);
    const config = resolveConfig({
      devices: [
        {
          id: 'plant',
          host: '127.0.0.1',
          port: modbusPort,
          pollMs: 50,
          timeoutMs: 1000,
          points: [
            { address: '%IX0.0', count: 8 },
            { address: '%QX0.0', count: 8 },
          ],
        },
      ],
    });
    gw = await startGateway({ port: 0, config, distDir: 'dist' });
  });
  afterAll(async () => {
    for (const p of pages.splice(0)) await p.close().catch(() => undefined);
    await gw?.close();
    await plant?.kill();
  });

  it('the dialog names device "plant" and its address; Cancel leaves the coil OFF on the device, Confirm drives it ON', async () => {
    const { page, errors } = await openApp(browser(), gw.url);
    pages.push(page);
    const sim = new SimPage(page);
    await sim.openExample('Motor start/stop (seal-in)');
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await expect.poll(() => gw.hub.status().armed).toBe(true);
    const coil = await sim.draw.cellPoint(0, 0, 9);
    const forceTrue = async () => {
      await page.mouse.click(coil.x, coil.y, { button: 'right' });
      await page.getByTestId('sim-context-menu').getByRole('menuitem', { name: 'Force TRUE' }).click();
    };
    await forceTrue();
    const dialog = page.getByTestId('hw-output-confirm');
    await expect.poll(() => dialog.count()).toBe(1);
    expect(await dialog.textContent()).toMatch(
      /Motor is output %QX0\.0 of device "plant" \(127\.0\.0\.1:\d+ unit \d+\)\./,
    );
    await dialog.getByTestId('hw-output-cancel').click();
    await scansPass(page, 20);
    expect(await plant.get('co', 0, 1)).toEqual([0]);

    await forceTrue();
    await dialog.getByTestId('hw-output-ok').click();
    await eventually(
      async () => (await plant.get('co', 0, 1))[0] === 1,
      10_000,
      'Motor ON on the pymodbus device after Confirm',
    );
    // Stop the program: the gateway writes the safe state; the forced motor is OFF on the device.
    await sim.button('pause').click();
    await eventually(
      async () => (await plant.get('co', 0, 1))[0] === 0,
      10_000,
      'Motor OFF on the device after Pause',
    );
    // Paused, a force still asks, and says when it would reach the device.
    await page.mouse.click(coil.x, coil.y, { button: 'right' });
    await page.getByTestId('sim-context-menu').getByRole('menuitem', { name: 'Force FALSE' }).click();
    expect(await dialog.getByTestId('hw-output-confirm-when').textContent()).toBe(
      'The outputs are held in the safe state now: the device gets it as soon as the program drives them (Run, or Arm).',
    );
    await dialog.getByTestId('hw-output-cancel').click();
    await expect.poll(() => dialog.count()).toBe(0);
    expect(await plant.get('co', 0, 1)).toEqual([0]);
    expect(errors).toEqual([]);
  });
});
