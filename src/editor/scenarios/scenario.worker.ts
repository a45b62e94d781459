// Web Worker: runs test scenarios off the page. The engine compiles a program to JavaScript
// (`new Function`), which the server's CSP allows in a worker only (src/gateway/staticFiles.ts), as
// for the simulator; and each scenario gets its own PLC here, so a run never touches the live
// simulation session (the simulator's worker). Created by scenarioRunner.ts.
import type { Project, Scenario } from '../../model/project';
import type { ScenarioResult } from '../../sim/scenario';
import { runScenarios } from './runScenarios';

export interface ScenarioRunRequest {
  readonly id: number;
  /** The project as JSON: far cheaper for the page to send than the object tree. */
  readonly projectText: string;
  readonly scenarios: readonly Scenario[];
}

export interface ScenarioRunReply {
  readonly id: number;
  readonly results: readonly ScenarioResult[];
}

const scope = self as unknown as DedicatedWorkerGlobalScope;
scope.onmessage = (event: MessageEvent<ScenarioRunRequest>) => {
  const project = JSON.parse(event.data.projectText) as Project;
  const reply: ScenarioRunReply = { id: event.data.id, results: runScenarios(project, event.data.scenarios) };
  scope.postMessage(reply);
};
