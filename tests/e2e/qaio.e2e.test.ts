// Exploratory QA of live I/O safety, the bugs it found, in a real Chromium against a gateway serving
// the built app with its simulated device. The device's coils are read back over Modbus TCP with
// mbpoll (coil 800 + n drives discrete input n), never from the page.
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { eventually, mbpoll } from '../gateway/helpers';
import { openApp } from './appPage';
import { hardwareLab } from './hardwareLab';
import { CHROMIUM_ARGS, CHROMIUM_PATH } from './browser';
import { SimPage } from './simPage';

describe('live I/O: leaving the page', () => {
  let gw: RunningGateway;
  // Users' browsers keep a page left for another address in the back/forward cache, frozen, with its
  // workers; Playwright turns that cache off by default, so this file's Chromium has it on again.
  let chromiumWithCache: Browser | undefined;
  beforeAll(async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: 0 } }), distDir: 'dist' });
    chromiumWithCache = await chromium.launch({ executablePath: CHROMIUM_PATH, args: CHROMIUM_ARGS, headless: true, ignoreDefaultArgs: ['--disable-back-forward-cache'] });
  });
  afterAll(async () => {
    await chromiumWithCache?.close();
    await gw?.close();
  });
  const browser = () => chromiumWithCache!;
  const pages: Page[] = [];
  afterEach(async () => {
    for (const p of pages.splice(0)) await p.close().catch(() => undefined);
    await mbpoll(port(), ['-t', '0', '-r', '800', '127.0.0.1', '0', '0']);
  });

  const port = () => gw.simulated?.modbusServerPort ?? 0;
  const { coils, deviceInput, connect, openOnHardware } = hardwareLab({ port, browser, url: () => gw.url, pages });

  /** The motor example running in plain simulation (no hardware), Start in the Watch table with TRUE prepared. */
  async function startPreparedInSimulation() {
    const { page, errors } = await openApp(browser(), gw.url);
    pages.push(page);
    const sim = new SimPage(page);
    await sim.openExample('Motor start/stop (seal-in)');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.tab('Watch');
    await page.getByTestId('watch-add-name').fill('Start');
    await page.getByTestId('watch-add').click();
    const start = page.getByTestId('watch-row-Start');
    await start.getByTestId('watch-input').fill('TRUE');
    return { page, errors, sim, start };
  }

  it('going to another address in the tab while outputs are ON switches them off at once and frees the lease; the page brought back is Stopped', async () => {
    const { page, errors, sim } = await openOnHardware('Motor start/stop (seal-in)');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await deviceInput(0, true);
    await eventually(async () => (await coils())[0] === 1, 10_000, 'Motor on the device');
    await deviceInput(0, false); // sealed in: the motor stays on by the program alone

    // The page goes into the back/forward cache, frozen. Its link must not stay open: the gateway
    // sees the controller go (not a watchdog trip later), writes the safe state and frees the lease.
    await page.goto('about:blank');
    await eventually(() => !gw.hub.status().armed, 10_000, 'disarmed');
    expect(gw.hub.status().disarm?.cause).toBe('controller-lost');
    expect(gw.hub.status().controller).toBe(false);
    await eventually(async () => (await coils())[0] === 0, 10_000, 'Motor off on the device');

    // The page opened next is the controller, not an observer of a frozen page's lease.
    const other = await openOnHardware('Motor start/stop (seal-in)');
    expect(gw.hub.status().controller).toBe(true);
    await other.page.close();

    // Back from the cache: Stopped, saying why, and nothing armed.
    await page.goBack({ waitUntil: 'commit' });
    await sim.waitForMode('Stopped');
    await expect.poll(() => page.getByTestId('sim-notice').textContent()).toMatch(/the page was left while linked to the hardware/);
    expect(gw.hub.status().armed).toBe(false);
    expect((await coils())[0]).toBe(0);
    expect(errors).toEqual([]);
  });

  it('a page that asked to be controller while another page holds the lease runs as observer, and its toolbar says its outputs are not driven', async () => {
    const a = await openOnHardware('Motor start/stop (seal-in)');
    await a.sim.button('run').click();
    await a.sim.waitForMode('Running');
    await expect.poll(() => gw.hub.status().armed).toBe(true);

    const { page, errors } = await openApp(browser(), gw.url);
    pages.push(page);
    const sim = new SimPage(page);
    await sim.openExample('Parts counter (CTU)');
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    expect(await panel.getByTestId('hw-role').inputValue()).toBe('controller');
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as observer');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await expect
      .poll(() => page.getByTestId('hw-run-observer').textContent())
      .toBe('Outputs not driven — this page is connected as observer (read only); another page is the controller. Disconnect and connect as controller to drive them.');
    expect(gw.hub.status().armed).toBe(true); // page A still drives
    await sim.button('pause').click();
    await sim.waitForMode('Paused');
    await page.getByTestId('hw-run-observer').waitFor({ state: 'detached' });
    expect(errors).toEqual([]);
    expect(a.errors).toEqual([]);
  });

  it('a prepared value typed for an input before the hardware was attached is not forced by F7 on the device: it asks for Force on hardware', async () => {
    // Not connected yet: Start is a plain input, and TRUE is prepared for it in the Watch table.
    const { page, errors, sim } = await startPreparedInSimulation();
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');

    // Connected as controller and running on the device: Start now comes from the device.
    await page.getByTestId('tab-hardware').click();
    await connect(page.getByTestId('hardware-panel'));
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await expect.poll(() => gw.hub.status().armed).toBe(true);
    await sim.tab('Watch');
    await page.getByTestId('watch-panel').click({ position: { x: 5, y: 5 } });
    await page.keyboard.press('F7');
    await expect.poll(() => page.getByTestId('status-bar').textContent()).toMatch(/Start not forced: forcing a field input \(%IX0\.0\) drives outputs on the hardware: confirm with its row's Force on hardware/);
    await page.keyboard.press('Control+F7');
    await expect.poll(() => page.getByTestId('status-bar').textContent()).toMatch(/Start not written: a field input \(%IX0\.0\) comes from the device/);
    const from = Number(await page.getByTestId('sim-scan').textContent());
    await expect.poll(async () => Number(await page.getByTestId('sim-scan').textContent()), { timeout: 30_000 }).toBeGreaterThan(from + 20);
    expect(await sim.value('Start')).toBe(false);
    expect(await sim.value('Motor')).toBe(false);
    expect((await coils())[0]).toBe(0);
    await sim.button('pause').click();
    expect(errors).toEqual([]);
  });

  it('a force made before the hardware was attached ends as the link opens as controller, and Run leaves the motor off', async () => {
    const { page, errors, sim, start } = await startPreparedInSimulation();
    await start.getByTestId('watch-force').click(); // in simulation: no hardware, no confirmation
    await expect.poll(() => start.getByTestId('watch-value').textContent()).toBe('TRUE F');
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');
    expect(await start.getByTestId('watch-value').textContent()).toBe('TRUE F'); // forces outlive Reset

    await page.getByTestId('tab-hardware').click();
    await connect(page.getByTestId('hardware-panel'));
    await expect
      .poll(() => page.getByTestId('sim-notice').textContent())
      .toMatch(/^Unforced Start \(%IX0\.0\): forces made before the hardware was attached are not carried onto it\./);
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await expect.poll(() => gw.hub.status().armed).toBe(true);
    const from = Number(await page.getByTestId('sim-scan').textContent());
    await expect.poll(async () => Number(await page.getByTestId('sim-scan').textContent()), { timeout: 30_000 }).toBeGreaterThan(from + 20);
    expect(await sim.value('Start')).toBe(false);
    expect(await sim.value('Motor')).toBe(false);
    expect((await coils())[0]).toBe(0);
    await sim.tab('Watch');
    expect(await start.getByTestId('watch-value').textContent()).toBe('FALSE');
    await sim.button('pause').click();
    expect(errors).toEqual([]);
  });
});
