// Issue 22, section 2 item 9: under the openplc profile, the line from a timer's Q into the next
// timer's IN was drawn lit every scan while Q was FALSE (the display took the block's ENO for every
// line leaving it). A file in the shape OpenPLC's Blink example has (TON then TOF, EN/ENO wired, a
// TC6 v2.01 file, so it imports under openplc) is imported, run, and stepped scan by scan: the Q
// line is drawn as Q is, the ENO line lit.
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { expect, test } from 'vitest';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();

test('an imported OpenPLC timer chain draws the TON.Q line as Q is, scan by scan', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  const sim = new SimPage(page);
  const text = await readFile(fileURLToPath(new URL('../fixtures/plcopen/timer-chain-openplc.xml', import.meta.url)), 'utf8');
  await editor.chooseFile('File', 'Import PLCopen XML…', { name: 'timer-chain.xml', mimeType: 'application/xml', text });
  const report = page.getByTestId('plcopen-report');
  await report.waitFor();
  expect(await report.getByTestId('plcopen-profile').textContent()).toContain('semantics profile openplc');
  await report.getByRole('button', { name: 'Open' }).click();
  await poll(async () => (await editor.project()).name).toBe('TimerChain');

  // Step scan by scan (20 ms each): Q is FALSE for 300 ms, then TRUE for a scan, while OffTimer holds the output.
  await sim.button('step-scan').click();
  await sim.waitForMode('Paused');
  const seen = { on: 0, off: 0 };
  for (let scan = 1; scan <= 40 && (seen.on < 1 || seen.off < 3); scan++) {
    const q = (await sim.value('OnTimer.Q')) === true;
    seen[q ? 'on' : 'off']++;
    // Row 1: the line from OnTimer.Q (columns 4 and 5) into OffTimer.IN; row 0: ENO into EN.
    // Paused, the drawing settles on the scan shown (the canvas redraws in the next frame).
    const drawn = async () => ({
      scan,
      q1: await sim.wireLit(0, 1, 4, 'middle'),
      q2: await sim.wireLit(0, 1, 5, 'middle'),
      eno: await sim.wireLit(0, 0, 4, 'middle'),
    });
    await poll(drawn).toEqual({ scan, q1: q, q2: q, eno: true });
    const before = await page.getByTestId('sim-scan').textContent();
    await sim.button('step-scan').click();
    await poll(() => page.getByTestId('sim-scan').textContent()).not.toBe(before);
  }
  expect(seen.on).toBeGreaterThanOrEqual(1);
  expect(seen.off).toBeGreaterThanOrEqual(3);
  expect(editor.errors).toEqual([]);
  await editor.close();
});
