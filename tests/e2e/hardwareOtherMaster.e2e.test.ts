// Issue 21.2, the page's side: in a real Chromium against the gateway serving the built app with a
// Modbus TCP device (Debian's pymodbus). A running program drives the motor; another Modbus master
// (mbpoll) switches it off. The Hardware panel says plainly what happened, the device row says the
// gateway stopped writing, and the running program does not switch the motor on again.
import type { Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { eventually, mbpoll, PyModbusServer } from '../gateway/helpers';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

describe('another Modbus master on the device, in the Hardware panel', () => {
  let plant: PyModbusServer;
  let gw: RunningGateway;
  let modbusPort = 0;
  beforeAll(async () => {
    modbusPort = await freeLoopbackPort();
    plant = await PyModbusServer.start(modbusPort);
    const config = resolveConfig({
      devices: [{ id: 'plant', host: '127.0.0.1', port: modbusPort, pollMs: 50, points: [{ address: '%IX0.0', count: 8 }, { address: '%QX0.0', count: 8 }] }],
    });
    gw = await startGateway({ port: 0, config, distDir: 'dist' });
  });
  afterAll(async () => {
    await gw?.close();
    await plant?.kill();
  });
  const browser = useChromium();
  const pages: Page[] = [];
  afterEach(async () => {
    for (const p of pages.splice(0)) await p.close().catch(() => undefined);
  });

  it('says "another Modbus master is writing device "plant"\'s outputs (%QX0.0 read back OFF, we wrote ON): disarmed" and leaves the motor off', async () => {
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
    await plant.set('di', 0, [1]); // Start pressed on the device
    await eventually(async () => (await plant.get('co', 0, 1))[0] === 1, 10_000, 'Motor ON on the device');
    await plant.set('di', 0, [0]); // released: the motor seals in

    // Another master switches the motor contactor off.
    await mbpoll(modbusPort, ['-t', '0', '-r', '0', '127.0.0.1', '0']);
    await expect
      .poll(() => panel.getByTestId('hw-disarm').textContent(), { timeout: 10_000 })
      .toMatch(/another Modbus master is writing device "plant"'s outputs \(%QX0\.0 read back OFF, we wrote ON\): disarmed/);
    expect(await panel.getByTestId('hw-device-plant').getByTestId('hw-device-outputs').textContent()).toMatch(/^not written by this gateway: another Modbus master/);
    // The program still runs and still wants the motor ON; the gateway no longer writes it.
    expect(await sim.value('Motor')).toBe(true);
    for (let i = 0; i < 10; i++) {
      await new Promise((r) => setTimeout(r, 50));
      expect(await plant.get('co', 0, 1)).toEqual([0]);
    }
    expect(errors).toEqual([]);
  });
});
