// The checker behind useDiagnostics: one result per project version, computed in a Web Worker
// (in the page when workers are unavailable). Requests are latest-wins: while one check runs,
// only the newest waiting version is checked next.
import type { Diagnostic } from '../../engine/api';
import type { Project } from '../../model/project';
import type { CheckRequest } from './check.worker';
import { runChecks } from './checkRun';
import { projectJson } from '../files/projectJson';
import { diffProject } from '../../sim/projectDelta';

const results = new WeakMap<Project, readonly Diagnostic[]>();
const listeners = new Set<() => void>();
let worker: Worker | null | undefined;
let running: { seq: number; project: Project } | undefined;
/** The version the worker holds (the last one sent): the next is sent as a difference from it. */
let sent: { seq: number; project: Project } | undefined;
let waiting: Project | undefined;
let seq = 0;

const notify = () => listeners.forEach((l) => l());

function startWorker(): Worker | null {
  if (typeof Worker === 'undefined') return null;
  try {
    const w = new Worker(new URL('./check.worker.ts', import.meta.url), {
      type: 'module',
      name: 'rungsmith-check',
    });
    w.onmessage = (e: MessageEvent<{ seq: number; diagnostics: Diagnostic[] }>) => {
      if (!running || e.data.seq !== running.seq) return;
      results.set(running.project, e.data.diagnostics);
      running = undefined;
      sendNext();
      notify();
    };
    w.onerror = (e) => {
      // The worker could not start or crashed: check in the page from now on.
      e.preventDefault();
      w.terminate();
      worker = null;
      sent = undefined;
      const pending = running?.project;
      running = undefined;
      if (pending) results.set(pending, runChecks(pending));
      sendNext();
      notify();
    };
    return w;
  } catch {
    return null;
  }
}

function sendNext() {
  const project = waiting;
  waiting = undefined;
  if (!project || results.has(project)) return;
  if (worker === undefined) worker = startWorker();
  if (!worker) {
    results.set(project, runChecks(project));
    return;
  }
  seq += 1;
  running = { seq, project };
  // After the first version, only what an edit changed travels (projectDelta.ts): the page does not
  // write the whole project as JSON on every edit, and the worker's copy keeps the networks the edit
  // did not touch as the same objects, whose graphs and findings the engine then reuses
  // (compile/graph.ts): a check of an edit at 650 networks is a fraction of a whole one, which
  // matters most while an online change compiles beside it on the same two cores.
  const request: CheckRequest = sent ? { seq, delta: diffProject(sent.project, sent.seq, project) } : { seq, projectText: projectJson(project) };
  sent = { seq, project };
  worker.postMessage(request);
}

/** The diagnostics of this project version if already checked. */
export const checkedDiagnostics = (project: Project): readonly Diagnostic[] | undefined =>
  results.get(project);

/** Asks for this project version to be checked; subscribers hear when a result arrives. */
export function requestCheck(project: Project): void {
  if (results.has(project) || running?.project === project) return;
  waiting = project;
  if (running) return;
  sendNext();
  if (results.has(project)) notify();
}

export function onChecked(listener: () => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}
