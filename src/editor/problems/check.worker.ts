// Web Worker: runs the engine's checks off the page's thread, so a large program never makes
// drawing or scrolling stutter. Created by checker.ts.
import type { Project } from '../../model/project';
import { runChecks } from './checkRun';

export interface CheckRequest {
  readonly seq: number;
  readonly project: Project;
}

const scope = self as unknown as DedicatedWorkerGlobalScope;
scope.onmessage = (event: MessageEvent<CheckRequest>) => {
  scope.postMessage({ seq: event.data.seq, diagnostics: runChecks(event.data.project) });
};
