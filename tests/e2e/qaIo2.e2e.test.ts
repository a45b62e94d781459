// Exploratory QA of live I/O safety, round 2: the page driving a device through the gateway, in a
// real Chromium against a gateway serving the built app. The device's coils are read independently
// over Modbus TCP (mbpoll for the gateway's simulated device; the pymodbus server's own registers
// for a real device), never from the page or the gateway.
import type { Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { ladder, vars } from '../engine/ladder';
import { box } from '../engine/stDebugProject';
import { io, stProject, textPou } from '../engine/stHelpers';
import { pou } from '../engine/userBlocksHelpers';
import { eventually, PyModbusServer } from '../gateway/helpers';
import { openApp, useChromium } from './appPage';
import { hardwareLab, useHardwareGateway } from './hardwareLab';
import { SimPage } from './simPage';

const browser = useChromium();

/** Lamp (%QX0.0) lit by the program; the device's input %IX0.1 sends an ST FB into a loop that never ends. */
function runawayProject() {
  const spin = textPou(
    'Spin',
    'FUNCTION_BLOCK',
    [...io('input', 'Run BOOL'), ...vars('N DINT')],
    'N := 0;\nWHILE Run DO\n  N := N + 1;\nEND_WHILE;',
  );
  const main = pou(
    'Main',
    'PROGRAM',
    vars('Go BOOL := TRUE', 'Lamp BOOL %QX0.0', 'Trig BOOL %IX0.1', 'S1 Spin'),
    [
      ladder(['[Go] (Lamp)']),
      ladder(['[Trig] # # .', '. # # .'], { boxes: [box('Spin', 0, 1, { instance: 'S1' })] }),
    ],
  );
  return { ...stProject([main, spin]), name: 'Runaway' };
}

/** Scans the page shows, to wait for some to pass. */
const scan = async (page: Page) => Number(await page.getByTestId('sim-scan').textContent());

describe('live I/O round 2: the simulated device', () => {
  const lab = useHardwareGateway(browser);
  const { coils, deviceInput, openOnHardware } = lab;

  it('a program that faults in a runaway loop while it drives a lamp: the lamp goes OFF on the device, the page says Faulted with the loop, the Hardware panel says the safe state is held', async () => {
    const { page, errors } = await openApp(browser(), lab.gateway().url);
    lab.pages.push(page);
    const sim = new SimPage(page);
    await sim.load(runawayProject());
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    await lab.connect(panel);
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await eventually(async () => (await coils())[0] === 1, 10_000, 'Lamp ON on the device');
    await deviceInput(1, true); // the loop's condition, from the field
    await sim.waitForMode('Faulted');
    await eventually(async () => (await coils())[0] === 0, 10_000, 'Lamp OFF on the device');
    await expect
      .poll(() => page.getByTestId('sim-fault').textContent())
      .toMatch(/Watchdog fault in S1 \(Spin\) line 2: .*looping in the loop at line 2/);
    expect(lab.gateway().hub.status().armed).toBe(false);
    await expect.poll(() => panel.getByTestId('hw-disarm').textContent()).toMatch(/held in the safe state/);
    expect((await coils())[0]).toBe(0);
    expect(errors).toEqual([]);
  });

  it("Safe state while running: Outputs not driven says why, whole, and its Arm is inside the window (in the one-line tool bar both were past the window's edge), and Arm drives the motor again", async () => {
    const { page, sim, panel } = await openOnHardware('Motor start/stop (seal-in)');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await deviceInput(0, true);
    await eventually(async () => (await coils())[0] === 1, 10_000, 'Motor ON on the device');
    await deviceInput(0, false);
    await panel.getByTestId('hw-safe').click();
    await eventually(async () => (await coils())[0] === 0, 10_000, 'safe state on the device');
    const badge = page.getByTestId('hw-run-disarmed');
    await expect
      .poll(() => badge.textContent())
      .toMatch(
        /^Outputs not driven — STOP or Safe state \(.*\): STOP \(.*\): outputs are held in the safe state until the controller arms again \(Run or Arm\)Arm$/,
      );
    // The Hardware panel names the refusal once ("Outputs refused: outputs refused: ..." before).
    await expect
      .poll(() => panel.getByTestId('hw-last-error').textContent())
      .toMatch(/^Outputs refused: STOP \(the controller sent stop\): outputs are held/);
    const window = page.viewportSize()!;
    for (const part of [badge.locator('.rs-hw-reason'), page.getByTestId('hw-run-arm')]) {
      const box = (await part.boundingBox())!;
      expect(box.x + box.width).toBeLessThanOrEqual(window.width);
      expect(box.x).toBeGreaterThanOrEqual(0);
      expect(box.width).toBeGreaterThan(20);
    }
    await page.getByTestId('hw-run-arm').click();
    await eventually(async () => (await coils())[0] === 1, 15_000, 'driven again after its Arm');
    await badge.waitFor({ state: 'detached' });
    await sim.button('pause').click();
    await eventually(async () => (await coils())[0] === 0, 10_000, 'Pause: safe state');
  });

  it('Warm restart while a sealed-in motor runs on the device: the motor (not RETAIN) restarts OFF in the program shown and OFF on the device; Reset (cold restart) stops and holds the safe state', async () => {
    const { page, sim } = await openOnHardware('Motor start/stop (seal-in)');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await deviceInput(0, true);
    await eventually(async () => (await coils())[0] === 1, 10_000, 'Motor ON on the device');
    await deviceInput(0, false);
    await page.getByTestId('sim-warm').click();
    await sim.waitForValue('Motor', false);
    await eventually(
      async () => (await coils())[0] === 0,
      10_000,
      'Motor OFF on the device after the warm restart',
    );
    expect(await sim.mode()).toBe('Running');
    const from = await scan(page);
    await expect.poll(() => scan(page), { timeout: 30_000 }).toBeGreaterThan(from + 20);
    expect((await coils())[0]).toBe(0);
    // Start again drives it (still armed: the restarted program is the one shown).
    await deviceInput(0, true);
    await eventually(async () => (await coils())[0] === 1, 10_000, 'Motor ON again');
    await deviceInput(0, false);
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');
    await eventually(async () => (await coils())[0] === 0, 10_000, 'Reset: safe state');
    expect(lab.gateway().hub.status()).toMatchObject({ armed: false, disarm: { cause: 'stop' } });
  });

  it("the page's tab crashes while a sealed-in motor runs: the gateway sees the controller go, the motor goes OFF on the device and the lease is free", async () => {
    const { page, sim } = await openOnHardware('Motor start/stop (seal-in)');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await deviceInput(0, true);
    await eventually(async () => (await coils())[0] === 1, 10_000, 'Motor ON on the device');
    await deviceInput(0, false); // sealed in: only the program keeps it on
    const cdp = await page.context().newCDPSession(page);
    void cdp.send('Page.crash').catch(() => undefined); // answered only by the crash
    await eventually(async () => (await coils())[0] === 0, 10_000, 'Motor OFF on the device');
    expect(lab.gateway().hub.status()).toMatchObject({
      armed: false,
      controller: false,
      disarm: { cause: 'controller-lost' },
    });
  });
});

/** The Motor example's I/O on a pymodbus server playing a real coupler: it outlives the gateway. */
describe('live I/O round 2: a real device (pymodbus) behind a gateway that stops, restarts and loses it', () => {
  let plant: PyModbusServer;
  let modbusPort = 0;
  let gw: RunningGateway | undefined;
  let httpPort = 0;
  const TOKEN = 'qa-io-2-device-token-0123456789';
  /** On the same port and token each time, so the page reconnects by itself as it would to a restarted gateway. */
  const startGw = async () => {
    gw = await startGateway({
      port: httpPort,
      token: TOKEN,
      distDir: 'dist',
      config: resolveConfig({
        devices: [
          {
            id: 'plant',
            host: '127.0.0.1',
            port: modbusPort,
            pollMs: 50,
            timeoutMs: 300,
            points: [
              { address: '%IX0.0', count: 2 },
              { address: '%QX0.0', count: 2 },
            ],
          },
        ],
      }),
    });
    httpPort = gw.port;
  };
  beforeAll(async () => {
    modbusPort = await freeLoopbackPort();
    plant = await PyModbusServer.start(modbusPort);
    await startGw();
  });
  afterAll(async () => {
    await gw?.close();
    await plant?.kill();
  });
  const pages: Page[] = [];
  afterEach(async () => {
    for (const p of pages.splice(0)) await p.close().catch(() => undefined);
    await plant.set('di', 0, [0, 0]);
  });
  const { openOnHardware } = hardwareLab({ port: () => modbusPort, browser, url: () => gw!.url, pages });
  /** The coupler's coils 0-1, read from the server itself. */
  const deviceCoils = () => plant.get('co', 0, 2);

  it('a motor forced ON on the hardware, the gateway stopped and started again: OFF on the device meanwhile, and the page says the force ended with the lost link; the motor stays OFF until Run or Arm', async () => {
    const { page, sim, panel } = await openOnHardware('Motor start/stop (seal-in)');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.tab('Watch');
    await page.getByTestId('watch-add-name').fill('Motor');
    await page.getByTestId('watch-add').click();
    const row = page.getByTestId('watch-row-Motor');
    await row.getByTestId('watch-input').fill('TRUE');
    await row.getByTestId('watch-force').click();
    await page.getByTestId('hw-output-ok').click(); // a real output: forced after its confirmation (hardwareForce.e2e.test.ts)
    await eventually(async () => (await deviceCoils())[0] === 1, 10_000, 'the forced motor ON on the device');

    await gw!.close(); // its shutdown writes the safe state last
    expect(await deviceCoils()).toEqual([0, 0]);
    await expect
      .poll(() => page.getByTestId('hw-run-link-lost').textContent())
      .toMatch(/^Outputs not driven — hardware link lost/);
    expect(await row.getByTestId('watch-value').textContent()).toMatch(/^TRUE F/); // still forced in the page while the link is down

    await startGw();
    await expect
      .poll(() => panel.getByTestId('hw-link').textContent(), { timeout: 30_000 })
      .toBe('Connected as controller');
    await expect
      .poll(() => page.getByTestId('sim-notice').textContent())
      .toMatch(
        /^Unforced Motor \(%QX0\.0\): the link to the gateway was lost and is open again; a force on the hardware ends with its link/,
      );
    // No longer forced (no F); sealed in, the program still holds it TRUE, and the device's OFF is shown beside it.
    await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('TRUE device: FALSE');
    await expect
      .poll(() => page.getByTestId('hw-run-disarmed').textContent())
      .toMatch(/^Outputs not driven — not armed since the gateway started/);
    const from = await scan(page);
    await expect.poll(() => scan(page), { timeout: 30_000 }).toBeGreaterThan(from + 20);
    expect(await deviceCoils()).toEqual([0, 0]);
  });

  it('the device lost while the page drives it (a coupler power-cycled): the page says so and why, its outputs show stale, the device comes back OFF and stays OFF until Arm', async () => {
    const { page, sim, panel } = await openOnHardware('Motor start/stop (seal-in)');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await plant.set('di', 0, [1]);
    await eventually(async () => (await deviceCoils())[0] === 1, 10_000, 'Motor ON on the device');
    await plant.set('di', 0, [0]);
    await plant.kill();
    await expect
      .poll(() => page.getByTestId('hw-run-disarmed').textContent(), { timeout: 15_000 })
      .toMatch(/^Outputs not driven — a device was lost .*device "plant" lost its connection/);
    // What the unreachable device's motor output holds is not known: the Hardware panel says stale, not good.
    const motorQuality = panel.getByTestId('hw-point-%QX0.0').locator('td').last();
    await expect.poll(() => motorQuality.textContent(), { timeout: 15_000 }).toBe('stale');
    plant = await PyModbusServer.start(modbusPort);
    await expect
      .poll(() => panel.getByTestId('hw-device-plant').getByTestId('hw-device-outputs').textContent(), {
        timeout: 30_000,
      })
      .toBe('safe state');
    await expect.poll(() => motorQuality.textContent()).toBe('good');
    const from = await scan(page);
    await expect.poll(() => scan(page), { timeout: 30_000 }).toBeGreaterThan(from + 20);
    expect(await sim.value('Motor')).toBe(true); // the program still wants it
    expect(await deviceCoils()).toEqual([0, 0]);
    await panel.getByTestId('hw-arm').click();
    await eventually(async () => (await deviceCoils())[0] === 1, 15_000, 'driven again after Arm');
    await sim.button('pause').click();
    await eventually(async () => (await deviceCoils())[0] === 0, 10_000, 'Pause: safe state');
  });
});
