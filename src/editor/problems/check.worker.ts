// Web Worker: runs the engine's checks off the page's thread, so a large program never makes
// drawing or scrolling stutter. Created by checker.ts.
import type { Project } from '../../model/project';
import { applyDelta, type ProjectDelta } from '../../sim/projectDelta';
import { runChecks } from './checkRun';

export type CheckRequest =
  | {
      readonly seq: number;
      /** The first version as JSON: far cheaper for the page to send than the object tree. */
      readonly projectText: string;
    }
  | {
      readonly seq: number;
      /** A later version as a difference from the one sent before it (its seq is `delta.base`). */
      readonly delta: ProjectDelta;
    };

const scope = self as unknown as DedicatedWorkerGlobalScope;
/** The last version received: the base of the next difference. */
let held: { seq: number; project: Project } | undefined;
scope.onmessage = (event: MessageEvent<CheckRequest>) => {
  const request = event.data;
  let project: Project;
  if ('delta' in request) {
    // Messages arrive in order, so the base is the version before; anything else is a bug (the
    // page then checks in its own thread: checker.ts onerror).
    if (held?.seq !== request.delta.base) throw new Error(`the checker's copy of the project is not the version ${request.delta.base}`);
    project = applyDelta(held.project, request.delta);
  } else project = JSON.parse(request.projectText) as Project;
  held = { seq: request.seq, project };
  scope.postMessage({ seq: request.seq, diagnostics: runChecks(project) });
};
