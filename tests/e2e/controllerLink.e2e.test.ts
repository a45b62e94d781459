// Issue 21, the controller link in a real Chromium against the gateway serving the built app:
// a 1 ms program whose outputs change every scan is not thrown out as a flooder (4); the lease
// heartbeat comes from the worker that runs the scan, so a blocked page does not trip it and a
// terminated worker ends it (5); a refused page stops driving, says why and offers Reconnect (4);
// paused, an input changed on the device is marked in the Watch (smaller item).
// Device coils are read back over Modbus TCP with mbpoll.
import type { Locator, Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project } from '../../src/model/project';
import { eventually, mbpoll, mbpollValues, TestClient } from '../gateway/helpers';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

/** Q AT %QX0.0 toggles every scan (a contact NOT Q drives the coil Q), at a 1 ms cycle. */
function toggler(): Project {
  const net = newNetwork({
    rows: 1,
    cols: 3,
    elements: [
      { id: 'c1' as ElementId, kind: 'contact', contact: 'NC', variable: 'Q', row: 0, col: 0 },
      { id: 'l1' as ElementId, kind: 'link', row: 0, col: 1 },
      { id: 'q1' as ElementId, kind: 'coil', coil: 'COIL', variable: 'Q', row: 0, col: 2 },
    ],
    vlinks: [],
  });
  const main = newPou('Main', { variables: [variable('Q', 'BOOL', { location: '%QX0.0' })], networks: [net] });
  return newProject('Toggler', { pous: [main], tasks: [{ name: 'Fast', cycleMs: 1, priority: 1, programs: [{ instance: 'Fast1', pou: 'Main' }] }] });
}

describe('controller link (issue 21)', () => {
  let gw: RunningGateway;
  beforeAll(async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ watchdogMs: 2000, simulated: { modbusPort: 0 } }), distDir: 'dist' });
  });
  afterAll(async () => {
    await gw?.close();
  });
  const browser = useChromium();
  const pages: Page[] = [];
  const observers: TestClient[] = [];
  afterEach(async () => {
    for (const o of observers.splice(0)) o.close();
    for (const p of pages.splice(0)) await p.close().catch(() => undefined);
    await eventually(() => !gw.hub.status().controller, 10_000, 'the lease released');
  });

  const coil0 = async () => mbpollValues(await mbpoll(gw.simulated?.modbusServerPort ?? 0, ['-t', '0', '-r', '0', '-c', '1', '127.0.0.1']))[0];

  async function runToggler(): Promise<{ page: Page; sim: SimPage; panel: Locator; errors: string[] }> {
    const { page, errors } = await openApp(browser(), gw.url);
    pages.push(page);
    const sim = new SimPage(page);
    await sim.load(toggler());
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await expect.poll(() => gw.hub.status().armed, { timeout: 15_000 }).toBe(true);
    return { page, sim, panel, errors };
  }

  /** Scans run on: the scan counter passes `n` more scans (a behaviour, not a time). */
  async function scansPass(page: Page, n: number) {
    const from = Number(await page.getByTestId('sim-scan').textContent());
    await expect.poll(async () => Number(await page.getByTestId('sim-scan').textContent()), { timeout: 60_000 }).toBeGreaterThan(from + n);
  }

  it('a 1 ms program changing its outputs every scan keeps the lease; a blocked page does not trip it; a terminated worker ends it', async () => {
    const { page, sim, panel } = await runToggler();
    // Thousands of output changes: the link stays open (coalesced to at most one image per poll).
    await scansPass(page, 3000);
    expect(await panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
    expect(gw.hub.status()).toMatchObject({ armed: true, controller: true, watchdog: { state: 'fed' } });

    // The page's main thread blocked for 5 s (two and a half watchdog periods): the worker keeps scanning
    // and sending. An observer sees the device written throughout and no trip.
    const observer = await TestClient.hello(gw.port, gw.token, 'observer');
    observers.push(observer);
    const from = observer.messages.length;
    await page.evaluate(() => {
      const end = Date.now() + 5000;
      while (Date.now() < end) {
        /* a page busy with something else */
      }
    });
    const during = observer.messages.slice(from);
    expect(during.some((m) => m.t === 'status' && (m.watchdog.state === 'tripped' || !m.armed))).toBe(false);
    expect(during.filter((m) => m.t === 'written' && m.values['%QX0.0'] !== undefined).length).toBeGreaterThanOrEqual(5);
    expect(gw.hub.status()).toMatchObject({ armed: true, controller: true, watchdog: { state: 'fed' } });
    // The device coil is still driven by the program: it keeps toggling.
    const seen = new Set<number | undefined>();
    await eventually(async () => {
      seen.add(await coil0());
      return seen.size === 2;
    }, 15_000, 'coil 0 toggled by the program');
    expect(await sim.mode()).toBe('Running');

    // The worker that runs the scan is gone: its link closes, the lease ends, outputs go safe.
    await page.evaluate(() => (window.rungsmith as unknown as { terminateSimulation(): void }).terminateSimulation());
    await observer.waitFor((m) => m.t === 'status' && !m.armed && m.disarm?.cause === 'controller-lost', 10_000, from);
    await eventually(async () => (await coil0()) === 0, 10_000, 'coil 0 OFF');
    await expect.poll(() => page.getByTestId('sim-notice').textContent(), { timeout: 15_000 }).toMatch(/simulator stopped/);
    // The simulation does not show Running for a program that no longer runs anywhere.
    await sim.waitForMode('Stopped');
    expect(gw.hub.status().armed).toBe(false);
  });

  it('paused on hardware, an input that changes on the device shows its device value in the Watch next to the stale one', async () => {
    const { page, errors } = await openApp(browser(), gw.url);
    pages.push(page);
    const sim = new SimPage(page);
    const setInput = (n: number, on: boolean) => mbpoll(gw.simulated?.modbusServerPort ?? 0, ['-t', '0', '-r', String(800 + n), '127.0.0.1', on ? '1' : '0']);
    await setInput(0, false);
    await sim.openExample('Motor start/stop (seal-in)');
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
    await sim.tab('Watch');
    await page.getByTestId('watch-add-name').fill('Start');
    await page.getByTestId('watch-add').click();
    const row = page.getByTestId('watch-row-Start');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('FALSE');
    await sim.button('pause').click();
    await sim.waitForMode('Paused');

    // Start pressed on the device while paused: the program has not read it; the Watch says so.
    await setInput(0, true);
    await expect.poll(() => row.getByTestId('watch-value').textContent(), { timeout: 15_000 }).toBe('FALSE device: TRUE');
    expect(await sim.value('Start')).toBe(false);
    // Run again: the program reads it, the two agree, the mark goes.
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await expect.poll(() => row.getByTestId('watch-value').textContent(), { timeout: 15_000 }).toBe('TRUE');
    await eventually(async () => (await coil0()) === 1, 10_000, 'Motor on the device');
    await sim.button('pause').click();
    await eventually(async () => (await coil0()) === 0, 10_000, 'safe state after Pause');
    await setInput(0, false);
    expect(errors).toEqual([]);
  });

  it('a page the gateway refuses stops driving, says why in plain words and offers Reconnect', async () => {
    const { page, panel, errors } = await runToggler();
    await eventually(async () => {
      const seen = new Set([await coil0(), await coil0(), await coil0()]);
      return seen.size === 2;
    }, 15_000, 'coil 0 driven');
    // Resync pressed far faster than anyone could: over the 200 messages/s budget, the gateway closes the link (1008).
    await page.evaluate(() => {
      const resync = [...document.querySelectorAll('button')].find((b) => b.textContent === 'Resync');
      for (let i = 0; i < 400; i++) resync?.click();
    });
    await expect.poll(() => panel.getByTestId('hw-link').textContent(), { timeout: 15_000 }).toBe('Refused');
    const problem = await panel.getByTestId('hw-problem').textContent();
    expect(problem).toMatch(/more than 200 messages per second/);
    expect(problem).toMatch(/no longer drives the outputs/);
    expect(await panel.getByTestId('hw-connect').textContent()).toBe('Reconnect');
    // The simulation does not pose as the controller of the link it lost.
    await expect.poll(() => page.getByTestId('sim-notice').textContent()).toMatch(/Hardware link lost while running .*no longer drives the outputs/);
    expect(await page.getByTestId('hw-run-link-lost').textContent()).toMatch(/^Outputs not driven — hardware link refused: the gateway closed the link/);
    await eventually(async () => (await coil0()) === 0, 10_000, 'coil 0 OFF (safe state)');
    expect(gw.hub.status()).toMatchObject({ armed: false, controller: false });

    // Reconnect: the link is back as controller; nothing arms by itself.
    await eventually(async () => {
      if ((await panel.getByTestId('hw-connect').textContent()) !== 'Reconnect') return false;
      await panel.getByTestId('hw-connect').click();
      try {
        await expect.poll(() => panel.getByTestId('hw-link').textContent(), { timeout: 3000 }).toBe('Connected as controller');
        return true;
      } catch {
        return false; // the message budget carried over from the refused link is still refilling
      }
    }, 30_000, 'reconnected');
    await expect.poll(() => page.getByTestId('hw-run-disarmed').textContent()).toMatch(/Outputs not driven/);
    expect(gw.hub.status().armed).toBe(false);
    expect(await coil0()).toBe(0);
    await page.getByTestId('sim-pause').click();
    expect(errors).toEqual([]);
  });
});
