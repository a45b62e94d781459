// A PLC programmer configures the tasks in the project tree: the interval and priority of the
// task, a second task running another instance of the program, a bad interval refused with the
// reason, and Run runs exactly the configured program instances; an event task on a BOOL global,
// whose program's networks say "not run" until the trigger first rises.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newPou, newProject } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { ladder, vars } from '../engine/ladder';
import { io } from '../engine/userBlocksHelpers';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Plant'));
});

const tasks = (): Promise<Project['tasks']> =>
  page.evaluate(() => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project.tasks)) as Project['tasks']);

async function setField(testId: string, text: string) {
  const field = page.getByTestId(testId);
  await field.fill(text);
  await field.press('Enter');
}

test('the tasks dialog edits interval and priority, adds a task running a second instance, refuses a bad interval', async () => {
  await page.getByTestId('tab-project').click();
  await page.getByTestId('tree-tasks-edit').click();
  await page.getByTestId('tasks-dialog').waitFor();
  const first = (await tasks())[0]!;

  await setField('task-cycle-0', '50');
  await setField('task-priority-0', '3');
  expect((await tasks())[0]).toMatchObject({ cycleMs: 50, priority: 3 });

  await setField('task-cycle-0', '0');
  await expect.poll(() => page.getByTestId('task-problem-0').textContent()).toMatch(/interval is whole milliseconds from 1 ms to 1 h/);
  expect((await tasks())[0]!.cycleMs).toBe(50);
  await setField('task-cycle-0', '40');
  expect(await page.getByTestId('task-problem-0').count()).toBe(0);
  expect((await tasks())[0]!.cycleMs).toBe(40);

  await page.getByTestId('task-add').click();
  await page.getByTestId('task-1').waitFor();
  await page.getByTestId('task-add-program-1').selectOption('Main');
  const now = await tasks();
  expect(now.map((t) => t.name)).toEqual([first.name, 'Task']);
  expect(now[1]!.programs).toEqual([{ instance: 'MainInstance2', pou: 'Main' }]);

  // The tree lists what the dialog configured.
  await page.getByTestId('tasks-close').click();
  await expect.poll(() => page.getByTestId('tree-task-Task').textContent()).toMatch(/every 20 ms, priority 1/);

  // Run runs both program instances, as a configuration.
  const sim = new SimPage(page);
  await sim.button('run').click();
  await sim.waitForMode('Running');
  const programs = await page.evaluate(
    () => (window.rungsmith as unknown as { simStore: { getState(): { layout?: { programs?: { instance: string }[] } } } }).simStore.getState().layout?.programs?.map((p) => p.instance),
  );
  expect(programs).toEqual([...first.programs.map((p) => p.instance), now[1]!.programs[0]!.instance]);
  await sim.button('pause').click();
  expect(errors).toEqual([]);
});

test('the dialog says what runs in which tick; the simulator scans on the common tick, its Cycle read-only', async () => {
  const schedule = () => page.getByTestId('tasks-schedule').textContent();
  await page.getByTestId('tree-tasks-edit').click();
  await page.getByTestId('tasks-dialog').waitFor();
  expect(await schedule()).toBe("Tick 20 ms: MainTask runs every 2nd tick (40 ms); Task every tick (20 ms). The simulator's Cycle is this tick.");
  await setField('task-cycle-1', '40');
  await expect.poll(schedule).toBe("Tick 40 ms: MainTask runs every tick (40 ms); Task every tick (40 ms). The simulator's Cycle starts at this interval and can be changed there.");
  await setField('task-cycle-1', '10');
  await expect.poll(schedule).toBe("Tick 10 ms: MainTask runs every 4th tick (40 ms); Task every tick (10 ms). The simulator's Cycle is this tick.");
  await page.getByTestId('tasks-close').click();

  const cycle = page.getByTestId('sim-cycle');
  await expect.poll(() => cycle.inputValue()).toBe('10');
  expect(await cycle.getAttribute('readonly')).not.toBeNull();
  // Eight scans from a cold restart are eight 10 ms ticks.
  const sim = new SimPage(page);
  await sim.button('reset').click();
  await page.getByTestId('sim-step-count').fill('8');
  await sim.button('step-n').click();
  const state = () =>
    page.evaluate(() => {
      const s = (window.rungsmith as unknown as { simStore: { getState(): { scan: number; timeMs: number; cycleMs: number } } }).simStore.getState();
      return `${s.scan} ${s.timeMs} ${s.cycleMs}`;
    });
  await expect.poll(state).toBe('8 70 10');
  expect(errors).toEqual([]);
});

/** Opens a POU's tab, as a click in the project tree does. */
const showPou = (name: string) =>
  page.evaluate((n) => {
    const d = window.rungsmith!.documentStore!.getState();
    d.setActivePou(d.project.pous.find((p) => p.name === n)!.id);
  }, name);

/** Main (task Cyclic, 10 ms) lights Lamp from Go; OnStart (task E, 20 ms until made an event task) toggles Seen. */
function eventPlant(): Project {
  const main = newPou('Main', { variables: io('external', 'Go BOOL', 'Lamp BOOL'), networks: [ladder(['[Go] (Lamp)'])] });
  const onStart = newPou('OnStart', { variables: io('external', 'Seen BOOL'), networks: [ladder(['[/Seen] (Seen)'])] });
  return newProject('Events', {
    pous: [main, onStart],
    globals: vars('Go BOOL', 'Lamp BOOL', 'Seen BOOL', 'StartPulse BOOL', 'Level INT'),
    tasks: [
      { name: 'Cyclic', cycleMs: 10, priority: 1, programs: [{ instance: 'MainInst', pou: 'Main' }] },
      { name: 'E', cycleMs: 20, priority: 0, programs: [{ instance: 'EvInst', pou: 'OnStart' }] },
    ],
  });
}

test('an event task: its trigger is chosen among the BOOL globals (one undo step); its program says "not run" until the trigger rises', async () => {
  const sim = new SimPage(page);
  await sim.button('reset').click();
  await sim.load(eventPlant());
  await page.getByTestId('tab-project').click();
  await page.getByTestId('tree-tasks-edit').click();
  await page.getByTestId('tasks-dialog').waitFor();
  const trigger = page.getByTestId('task-single-1');
  expect(await trigger.locator('option').allTextContents()).toEqual(['(nothing: cyclic)', 'Go', 'Lamp', 'Seen', 'StartPulse']);
  await trigger.selectOption('StartPulse');
  await expect.poll(async () => (await tasks())[1]).toEqual({ name: 'E', cycleMs: 20, single: 'StartPulse', priority: 0, programs: [{ instance: 'EvInst', pou: 'OnStart' }] });
  const schedule = () => page.getByTestId('tasks-schedule').textContent();
  await expect.poll(schedule).toBe("Tick 10 ms: Cyclic runs every tick (10 ms); E runs when StartPulse rises. The simulator's Cycle is this tick.");
  // One undo step: undo makes it cyclic again (the field shows it), redo brings the trigger back.
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  await expect.poll(() => page.getByTestId('task-single-1').inputValue()).toBe('');
  expect('single' in (await tasks())[1]!).toBe(false);
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().redo());
  await expect.poll(() => page.getByTestId('task-single-1').inputValue()).toBe('StartPulse');
  // An event task may have no interval: the field is emptied, the trigger runs it.
  await setField('task-cycle-1', '');
  await expect.poll(async () => (await tasks())[1]!.cycleMs).toBe(0);
  await page.getByTestId('tasks-close').click();
  await expect.poll(() => page.getByTestId('tree-task-E').textContent()).toMatch(/when StartPulse rises, priority 0/);

  // Show OnStart, step one scan: its task was not due (no rise yet), so its network did not run.
  await showPou('OnStart');
  await sim.button('reset').click();
  await sim.button('step-scan').click();
  const marker = page.locator('.rs-sim-skipped');
  await expect.poll(() => marker.allTextContents()).toEqual(['not run']);
  await sim.button('step-scan').click();
  await expect.poll(() => marker.allTextContents()).toEqual(['not run']);
  // The trigger rises (written from the watch table): the next scan runs OnStart once; no marker.
  await page.evaluate(() =>
    (window.rungsmith as unknown as { simStore: { getState(): { write(n: string, i: { value: boolean }): void } } }).simStore.getState().write('StartPulse', { value: true }),
  );
  await sim.button('step-scan').click();
  await sim.waitForValue('Seen', true);
  await expect.poll(() => marker.count()).toBe(0);
  // Main's task is due in every tick: its network never says "not run".
  await showPou('Main');
  await sim.button('step-scan').click();
  await expect.poll(() => marker.count()).toBe(0);
  expect(await sim.value('Seen')).toBe(true);
  expect(errors).toEqual([]);
});
