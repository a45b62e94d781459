// Where the Tests panel's scenarios run: in a Web Worker of their own (scenario.worker.ts). The
// page may not compile programs (the server's CSP forbids `new Function` outside workers), and a
// scenario must never touch the live simulation session, so neither the page nor the simulator's
// worker runs them. Without Worker support (Node) the batch runs in place.
import type { Project, Scenario } from '../../model/project';
import type { ScenarioResult } from '../../sim/scenario';
import { projectJson } from '../files/projectJson';
import { runScenarios } from './runScenarios';
import type { ScenarioRunReply, ScenarioRunRequest } from './scenario.worker';

interface Pending {
  readonly scenarios: readonly Scenario[];
  resolve(results: ScenarioResult[]): void;
}

let worker: Worker | undefined;
const pending = new Map<number, Pending>();
let nextId = 0;

/** Every waiting run gets an error per scenario (the worker could not start or crashed). */
function failAll(message: string) {
  for (const [id, p] of pending) {
    pending.delete(id);
    p.resolve(p.scenarios.map((sc) => ({ name: sc.name, ok: false, scans: 0, divergences: [], error: message })));
  }
}

function ensureWorker(): Worker {
  if (worker) return worker;
  const w = new Worker(new URL('./scenario.worker.ts', import.meta.url), { type: 'module', name: 'rungsmith-scenarios' });
  w.onmessage = (e: MessageEvent<ScenarioRunReply>) => {
    const p = pending.get(e.data.id);
    if (!p) return;
    pending.delete(e.data.id);
    p.resolve([...e.data.results]);
  };
  w.onerror = (e) => {
    // Not run in the page instead: there the CSP forbids compiling, and the result would be a lie.
    e.preventDefault();
    w.terminate();
    worker = undefined;
    failAll(`the scenario runner stopped: ${e.message || 'the worker could not start'}`);
  };
  worker = w;
  return w;
}

/** Runs the scenarios against this project version, each from a cold restart; results in order. */
export function runScenariosOffPage(project: Project, scenarios: readonly Scenario[]): Promise<ScenarioResult[]> {
  if (typeof Worker === 'undefined') return Promise.resolve(runScenarios(project, scenarios));
  return new Promise((resolve) => {
    const id = ++nextId;
    pending.set(id, { scenarios, resolve });
    const request: ScenarioRunRequest = { id, projectText: projectJson(project), scenarios };
    ensureWorker().postMessage(request);
  });
}
