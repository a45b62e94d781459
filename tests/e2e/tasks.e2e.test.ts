// A PLC programmer configures the tasks in the project tree: the interval and priority of the
// task, a second task running another instance of the program, a bad interval refused with the
// reason, and Run runs exactly the configured program instances.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
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
