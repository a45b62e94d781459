// Runs a batch of test scenarios, each from a cold restart on its own PLC. Called in the scenario
// worker (scenario.worker.ts); the page calls it only where there are no workers (Node tests).
import type { Project, Scenario } from '../../model/project';
import { runScenario, type ScenarioResult } from '../../sim/scenario';

/** Each scenario's result, in order; an exception becomes that scenario's error, not a lost run. */
export function runScenarios(project: Project, scenarios: readonly Scenario[]): ScenarioResult[] {
  return scenarios.map((sc) => {
    try {
      return runScenario(project, sc).result;
    } catch (e) {
      return { name: sc.name, ok: false, scans: 0, divergences: [], error: `could not run: ${(e as Error).message}` };
    }
  });
}
