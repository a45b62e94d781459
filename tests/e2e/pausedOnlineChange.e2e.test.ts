// Issue 22, section 2 item 10: an online change applied while paused (a variable renamed) marked
// every network "not run" and showed every input OFF until the next step. The canvas and the
// values keep showing the last scan, mapped to the new program, until the program runs again.
import { expect, test } from 'vitest';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();

test('renaming a variable while paused keeps the last scan on screen: inputs ON, networks run, power drawn', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  const sim = new SimPage(page);
  await sim.runExample('Motor start/stop (seal-in)');
  // Start switched on (a double-click on its contact while running), the motor seals in.
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('Start', true);
  await sim.waitForValue('Motor', true);
  await sim.button('pause').click();
  await sim.waitForMode('Paused');
  const scan = await page.getByTestId('sim-scan').textContent();
  const drawn = async () => ({
    start: await sim.wireLit(0, 0, 0),
    seal: await sim.wireLit(0, 1, 0),
    notRun: await page.locator('.rs-sim-skipped').count(),
  });
  await poll(drawn).toEqual({ start: true, seal: true, notRun: 0 });

  // Rename Motor to Pump in the variable table while paused: an online change.
  await editor.tab('Variables');
  const name = editor.variableRow('Motor').getByLabel('Name');
  await editor.fill(name, 'Pump');
  await poll(() => page.getByTestId('sim-online-applied').textContent()).toMatch(/^Online change applied at scan/);
  await page.waitForFunction(() =>
    (window.rungsmith as unknown as { simStore: { getState(): { layout?: { variables: { name: string }[] } } } }).simStore
      .getState()
      .layout?.variables.some((v) => v.name === 'Pump'),
  );
  expect(await sim.mode()).toBe('Paused');
  expect(await page.getByTestId('sim-scan').textContent()).toBe(scan);
  // Still the last scan: Start ON, the network ran, its wires lit (Pump is a new name: its value
  // comes with the next scan; values carry by name).
  expect(await sim.value('Start')).toBe(true);
  await poll(drawn).toEqual({ start: true, seal: true, notRun: 0 });

  // The next step runs the new program: Start still pressed, Pump still on.
  await sim.button('step-scan').click();
  await poll(() => page.getByTestId('sim-scan').textContent()).not.toBe(scan);
  expect(await sim.value('Start')).toBe(true);
  expect(await sim.value('Pump')).toBe(true);
  await poll(drawn).toEqual({ start: true, seal: true, notRun: 0 });
  expect(editor.errors).toEqual([]);
  await editor.close();
});
