// A page on the hardware against the gateway's simulated device, as the live I/O tests drive it: the
// device's coils read back over Modbus TCP with mbpoll (never from the page), its discrete inputs set
// the same way (coil 800 + n drives discrete input n), and a page opened on an example and connected
// as controller.
import type { Browser, Locator, Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, expect } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { mbpoll, mbpollValues } from '../gateway/helpers';
import { openApp } from './appPage';
import { SimPage } from './simPage';

export interface HardwareLabOptions {
  /** The simulated device's Modbus TCP port (known once the gateway runs). */
  readonly port: () => number;
  readonly browser: () => Browser;
  readonly url: () => string;
  /** Pages opened, for the test file to close after each test. */
  readonly pages: Page[];
}

export function hardwareLab({ port, browser, url, pages }: HardwareLabOptions) {
  /** Device coils 0.. (the %QX0.x outputs as the device holds them). */
  const coils = async (count = 2) => mbpollValues(await mbpoll(port(), ['-t', '0', '-r', '0', '-c', String(count), '127.0.0.1']));
  /** Sets discrete input n (%IX0.n) on the device, as a field device would. */
  const deviceInput = (n: number, on: boolean) => mbpoll(port(), ['-t', '0', '-r', String(800 + n), '127.0.0.1', on ? '1' : '0']);
  /** The device's inputs back off, as found. */
  const inputsOff = () => mbpoll(port(), ['-t', '0', '-r', '800', '127.0.0.1', '0', '0']);

  async function connect(panel: Locator) {
    await panel.getByTestId('hw-connect').click();
    await expect.poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
  }

  /** A new page with `example` open and its Hardware tab connected as controller. */
  async function openOnHardware(example: string) {
    const { page, errors } = await openApp(browser(), url());
    pages.push(page);
    const sim = new SimPage(page);
    await sim.openExample(example);
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    await connect(panel);
    return { page, errors, sim, panel };
  }

  return { coils, deviceInput, inputsOff, connect, openOnHardware };
}

/**
 * For a describe block: the gateway serving the built app with its simulated device, started before
 * its tests and closed after them; after each test the pages it opened are closed and the device's
 * inputs are off again, as found. With the lab on it.
 */
export function useHardwareGateway(browser: () => Browser) {
  let gw: RunningGateway;
  const pages: Page[] = [];
  beforeAll(async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: 0 } }), distDir: 'dist' });
  });
  afterAll(async () => {
    await gw?.close();
  });
  const port = () => gw.simulated?.modbusServerPort ?? 0;
  afterEach(async () => {
    for (const p of pages.splice(0)) await p.close().catch(() => undefined);
    await mbpoll(port(), ['-t', '0', '-r', '800', '127.0.0.1', '0', '0', '0', '0']);
  });
  return { gateway: () => gw, port, pages, ...hardwareLab({ port, browser, url: () => gw.url, pages }) };
}

