// Web Worker: runs the engine's checks off the page's thread, so a large program never makes
// drawing or scrolling stutter. Created by checker.ts.
import type { Project } from '../../model/project';
import { runChecks } from './checkRun';

export interface CheckRequest {
  readonly seq: number;
  /** The project as JSON: far cheaper for the page to send than the object tree. */
  readonly projectText: string;
}

const scope = self as unknown as DedicatedWorkerGlobalScope;
scope.onmessage = (event: MessageEvent<CheckRequest>) => {
  const project = JSON.parse(event.data.projectText) as Project;
  scope.postMessage({ seq: event.data.seq, diagnostics: runChecks(project) });
};
