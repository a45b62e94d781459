// Issue 21.2, the page's side: in a real Chromium against the gateway serving the built app with a
// Modbus TCP device (Debian's pymodbus). A running program drives the motor; another Modbus master
// (mbpoll) switches it off. The Hardware panel says plainly what happened, the device row says the
// gateway stopped writing, and the running program does not switch the motor on again.
// Issue 21.3 too: Safe state while the device answers slower than the timeout: the device row says
// "safe state pending for N s" until the slow device acknowledges it, and the motor ends OFF.
import type { Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { eventually, mbpoll, PyModbusServer } from '../gateway/helpers';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

describe('another Modbus master and a slow device, in the Hardware panel', () => {
  let plant: PyModbusServer;
  let gw: RunningGateway | undefined;
  let modbusPort = 0;
  beforeAll(async () => {
    modbusPort = await freeLoopbackPort();
    plant = await PyModbusServer.start(modbusPort);
  });
  afterAll(async () => {
    await plant?.kill();
  });
  const browser = useChromium();
  const pages: Page[] = [];
  afterEach(async () => {
    for (const p of pages.splice(0)) await p.close().catch(() => undefined);
    await gw?.close();
    gw = undefined;
    await plant.mode('normal');
    await plant.set('co', 0, [0]);
  });

  /** A gateway on the device serving the built app; the motor example running on it, the motor ON. */
  async function motorRunning(timeoutMs = 1000) {
    const config = resolveConfig({
      devices: [{ id: 'plant', host: '127.0.0.1', port: modbusPort, pollMs: 50, timeoutMs, points: [{ address: '%IX0.0', count: 8 }, { address: '%QX0.0', count: 8 }] }],
    });
    gw = await startGateway({ port: 0, config, distDir: 'dist' });
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
    return { page, errors, sim, panel };
  }

  it('Safe state while the device answers in 2.5x the timeout: "safe state pending for N s", then the slow device acknowledges it and the motor is OFF', async () => {
    const { errors, panel } = await motorRunning(400);
    await plant.mode('slow', 1000);
    await panel.getByTestId('hw-safe').click();
    const outputs = panel.getByTestId('hw-device-plant').getByTestId('hw-device-outputs');
    await expect.poll(() => outputs.textContent(), { timeout: 15_000 }).toMatch(/^safe state pending for \d+ s \(not acknowledged yet\)$/);
    // Still slow: the safe write waits for the answer instead of being abandoned to a reconnect.
    await eventually(async () => (await plant.get('co', 0, 1))[0] === 0, 15_000, 'Motor OFF while the device is slow');
    await expect.poll(() => outputs.textContent(), { timeout: 15_000 }).toBe('safe state');
    expect(errors).toEqual([]);
  });

  it('says "another Modbus master is writing device "plant"\'s outputs (%QX0.0 read back OFF, we wrote ON): disarmed" and leaves the motor off', async () => {
    const { errors, sim, panel } = await motorRunning();

    // Another master switches the motor contactor off, cyclically as masters do (a single write that
    // lands between the gateway's read-back and its write is overwritten unseen: GATEWAY.md).
    const disarm = panel.getByTestId('hw-disarm');
    for (let i = 0; i < 50 && !/another Modbus master/.test((await disarm.count()) ? ((await disarm.textContent()) ?? '') : ''); i++) {
      await mbpoll(modbusPort, ['-t', '0', '-r', '0', '127.0.0.1', '0']);
      await new Promise((r) => setTimeout(r, 150));
    }
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
