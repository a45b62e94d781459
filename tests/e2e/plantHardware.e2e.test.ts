// A machine in the Plant panel and real I/O (issue 26 with issue 10's safety), in a real Chromium
// against the gateway serving the built app with its simulated device: while the page drives the
// hardware, the machine is set aside, so the program's inputs are the device's, never a simulated
// sensor deciding what real outputs do; disconnected, the machine is back. Device inputs are set over
// Modbus TCP with mbpoll (coil 800 + n drives discrete input n).
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { useChromium } from './appPage';
import { useHardwareGateway } from './hardwareLab';

describe('a machine and the hardware', () => {
  const { coils, deviceInput, openOnHardware } = useHardwareGateway(useChromium());
  const attachedMachine = (page: Page) =>
    page.evaluate(() => (window.rungsmith as unknown as { simStore: { getState(): { plant?: { id: string } } } }).simStore.getState().plant?.id);

  it('connected as controller, the tank is set aside and the program reads the device; disconnected, the tank is back', async () => {
    const { page, errors, sim, panel } = await openOnHardware('Tank level control (machine: tank)');
    // Set aside, said in the Plant panel and in the toolbar's notice.
    await expect.poll(() => attachedMachine(page)).toBeUndefined();
    await sim.tab('Plant');
    await expect.poll(() => page.getByTestId('plant-status').textContent()).toMatch(/^Set aside while this page drives the hardware/);
    expect(await page.getByTestId('sim-notice').textContent()).toContain('The machine tank is set aside while the hardware is attached');
    // The device says the water is above the low switch (a tank at its initial 100 L would say it is not).
    await deviceInput(2, true);
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.waitForValue('LowLevel', true);
    const from = Number(await page.getByTestId('sim-scan').textContent());
    await expect.poll(async () => Number(await page.getByTestId('sim-scan').textContent()), { timeout: 30_000 }).toBeGreaterThan(from + 20);
    expect(await sim.value('LowLevel')).toBe(true);
    // Not started: nothing driven on the device.
    expect(await coils(4)).toEqual([0, 0, 0, 0]);
    await sim.button('pause').click();
    await sim.waitForMode('Paused');
    await page.getByTestId('tab-hardware').click();
    await panel.getByTestId('hw-connect').click(); // Disconnect
    await expect.poll(() => attachedMachine(page)).toBe('tank');
    await sim.tab('Plant');
    await expect.poll(() => page.getByTestId('plant-status').textContent()).not.toMatch(/^Set aside/);
    expect(errors).toEqual([]);
  });
});
