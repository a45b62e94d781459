// The Hardware panel in a real Chromium, against the gateway serving the built app.
import type { Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { eventually, mbpoll, mbpollValues } from '../gateway/helpers';
import { openApp, useChromium } from './appPage';
import { collectPageErrors } from './browser';
import { SimPage } from './simPage';

describe('Hardware panel', () => {
  let gw: RunningGateway;
  let page: Page;
  let errors: string[];

  beforeAll(async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: 0 } }), distDir: 'dist' });
  });
  afterAll(async () => {
    await gw?.close();
  });
  const browser = useChromium();
  beforeAll(async () => {
    page = await browser().newPage();
    errors = collectPageErrors(page);
  });

  // A journey that fails half-way must still close its page, or it keeps the controller lease and
  // the next journey connects as observer.
  const journeys: Page[] = [];
  afterEach(async () => {
    for (const j of journeys.splice(0)) await j.close().catch(() => undefined);
  });

  /** A second page on the gateway's app: the motor example open, the Hardware panel connected as controller. */
  async function openMotorOnHardware() {
    const { page: journey, errors: journeyErrors } = await openApp(browser(), gw.url);
    journeys.push(journey);
    const sim = new SimPage(journey);
    await sim.openExample('Motor start/stop (seal-in)');
    await journey.getByTestId('tab-hardware').click();
    const panel = journey.getByTestId('hardware-panel');
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
    return { journey, journeyErrors, sim, panel };
  }

  it('opens from the gateway URL, connects with the token from the fragment and shows the simulated points', async () => {
    await page.goto(gw.url);
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    await expect.poll(() => panel.getByTestId('hw-url').inputValue()).toBe(`http://127.0.0.1:${gw.port}/`);
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
    await expect.poll(() => panel.getByTestId('hw-device-sim').textContent()).toContain('online');
    expect(await panel.getByTestId('hw-points').locator('tbody tr').count()).toBe(40);
    // The gateway starts disarmed; the panel says why and offers Arm (the device is online).
    expect(await panel.getByTestId('hw-watchdog').textContent()).toContain('Outputs disarmed');
    expect(await panel.getByTestId('hw-disarm').textContent()).toContain('not armed since the gateway started');
    expect(await panel.getByTestId('hw-device-sim').getByTestId('hw-device-outputs').textContent()).toBe('safe state');
    expect(await panel.getByTestId('hw-arm').isEnabled()).toBe(true);
  });

  it('sets a simulated input from the panel, visible to mbpoll as a discrete input', async () => {
    const row = page.getByTestId('hw-point-%IX0.3');
    await row.getByTestId('hw-switch').click();
    await expect.poll(() => row.getByTestId('hw-switch').getAttribute('aria-checked')).toBe('true');
    const port = gw.simulated?.modbusServerPort ?? 0;
    expect(mbpollValues(await mbpoll(port, ['-t', '1', '-r', '0', '-c', '4', '127.0.0.1']))).toEqual([0, 0, 0, 1]);

    const word = page.getByTestId('hw-point-%IW1').getByTestId('hw-word');
    await word.fill('4321');
    await word.press('Enter');
    await eventually(async () => mbpollValues(await mbpoll(port, ['-t', '3', '-r', '1', '127.0.0.1']))[0] === 4321, 5000, 'register set');
  });

  it('shows outputs written by another controller live, and the panel as observer cannot re-arm', async () => {
    // Reconnect this page as observer while a test client holds the lease.
    const panel = page.getByTestId('hardware-panel');
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Not connected');
    await panel.getByTestId('hw-role').selectOption('observer');
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as observer');
    expect(await panel.getByTestId('hw-arm').isDisabled()).toBe(true);
    gw.hub.claim('test-controller', 'controller');
    gw.hub.arm();
    gw.hub.outputs(new Map([['%QX0.5', true]]));
    await expect.poll(() => page.getByTestId('hw-point-%QX0.5').getByTestId('hw-value').textContent()).toBe('TRUE');
    await gw.hub.stop('test over');
    await gw.hub.release('test-controller');
    expect(errors).toEqual([]);
  });

  it('runs the motor example on the simulated device: Start from the panel lights the Motor coil and its Modbus coil', async () => {
    const { journey, journeyErrors, sim, panel } = await openMotorOnHardware();
    // The example's Start, Stop and Motor are bound to the gateway's points: no mapping problems.
    expect(await panel.getByTestId('hw-mapping').count()).toBe(0);
    await expect.poll(() => panel.getByTestId('hw-point-%IX0.0').locator('td').nth(1).textContent()).toBe('Start');

    await sim.button('run').click();
    await sim.waitForMode('Running');
    const port = gw.simulated?.modbusServerPort ?? 0;
    const start = panel.getByTestId('hw-point-%IX0.0').getByTestId('hw-switch');
    await start.click(); // Start pressed
    await sim.waitForValue('Start', true);
    await sim.waitForValue('Motor', true);
    await start.click(); // Start released: Motor seals in
    await sim.waitForValue('Start', false);
    await expect.poll(() => sim.wireLit(0, 0, 9)).toBe(true);
    expect(await sim.value('Motor')).toBe(true);
    await expect.poll(() => panel.getByTestId('hw-point-%QX0.0').getByTestId('hw-value').textContent()).toBe('TRUE');
    expect(mbpollValues(await mbpoll(port, ['-t', '0', '-r', '0', '-c', '2', '127.0.0.1']))).toEqual([1, 0]);

    // Pause: the gateway writes the safe state.
    await sim.button('pause').click();
    await eventually(async () => mbpollValues(await mbpoll(port, ['-t', '0', '-r', '0', '127.0.0.1']))[0] === 0, 5000, 'safe state after pause');
    expect(journeyErrors).toEqual([]);
    await journey.close();
  });

  it('steps the motor example on the simulated device after a confirmation, and keeps the lease fed while paused', async () => {
    const { journey, journeyErrors, sim, panel } = await openMotorOnHardware();
    const port = gw.simulated?.modbusServerPort ?? 0;
    const coil0 = async () => mbpollValues(await mbpoll(port, ['-t', '0', '-r', '0', '127.0.0.1']))[0];

    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.button('pause').click();
    await sim.waitForMode('Paused');
    const scan = Number(await journey.getByTestId('sim-scan').textContent());
    expect(await coil0()).toBe(0);

    // Start pressed on the device from outside (coil 800 drives discrete input 0 = %IX0.0).
    await mbpoll(port, ['-t', '0', '-r', '800', '127.0.0.1', '1']);
    await expect.poll(() => panel.getByTestId('hw-point-%IX0.0').getByTestId('hw-switch').getAttribute('aria-checked')).toBe('true');
    expect(await sim.value('Start')).toBe(false); // paused: the program has not read it yet

    // Stepping asks first; cancelling does not step.
    await sim.button('step-scan').click();
    const dialog = journey.getByRole('alertdialog', { name: 'Step with real outputs?' });
    await dialog.waitFor();
    expect(await dialog.textContent()).toContain('drives the real outputs');
    // Pause disarmed the gateway (STOP latches): the dialog says so, and that confirming arms.
    expect(await dialog.getByTestId('hw-step-watchdog').textContent()).toMatch(/Outputs disarmed; watchdog 1000 ms/);
    expect(await dialog.getByTestId('hw-step-disarmed').textContent()).toMatch(/STOP.*Confirming arms them/);
    expect(await journey.evaluate(() => document.activeElement?.textContent)).toBe('Cancel');
    await journey.keyboard.press('Escape');
    await dialog.waitFor({ state: 'detached' });
    expect(Number(await journey.getByTestId('sim-scan').textContent())).toBe(scan);
    expect(await coil0()).toBe(0);

    // Confirmed: the stepped scan reads Start from the device and Motor reaches the device's coil.
    await sim.button('step-scan').click();
    await dialog.getByTestId('hw-step-ok').click();
    await sim.waitForValue('Start', true);
    await sim.waitForValue('Motor', true);
    expect(Number(await journey.getByTestId('sim-scan').textContent())).toBe(scan + 1);
    await eventually(async () => (await coil0()) === 1, 5000, 'Motor coil on the device');
    const badge = journey.getByTestId('hw-stepping');
    await expect.poll(() => badge.textContent()).toMatch(/Outputs armed; watchdog 1000 ms,\s*fed/);

    // Paused in stepping mode for longer than the watchdog: the lease stays armed and fed.
    await journey.waitForTimeout(2500);
    expect(gw.hub.status()).toMatchObject({ armed: true, watchdog: { ms: 1000, state: 'fed' } });
    expect(await coil0()).toBe(1);

    // The next step does not ask again; Start released on the device, the motor seals in.
    await mbpoll(port, ['-t', '0', '-r', '800', '127.0.0.1', '0']);
    await expect.poll(() => panel.getByTestId('hw-point-%IX0.0').getByTestId('hw-switch').getAttribute('aria-checked')).toBe('false');
    await sim.button('step-scan').click();
    await sim.waitForValue('Start', false);
    expect(await dialog.count()).toBe(0);
    expect(await sim.value('Motor')).toBe(true);
    expect(await coil0()).toBe(1);

    // Reset ends hardware stepping: the gateway writes the safe state.
    await sim.button('reset').click();
    await eventually(async () => (await coil0()) === 0, 5000, 'safe state after reset');
    await badge.waitFor({ state: 'detached' });
    expect(gw.hub.status().watchdog.state).toBe('idle');
    expect(journeyErrors).toEqual([]);
    await journey.close();
  });
});
