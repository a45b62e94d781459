// Live diagnostics of the open project: checked shortly after the document stops changing, in a
// Web Worker, so drawing never waits for the checks. One result per project version is shared
// by every caller (problems list, canvas markers, status bar).
import { useEffect, useMemo, useState } from 'react';
import type { Diagnostic } from '../../engine/api';
import type { Project } from '../../model/project';
import { selectProject, useDocument } from '../../store/documentStore';
import { whenIdle } from '../files/projectJson';
import { checkedDiagnostics, onChecked, requestCheck } from './checker';

/** Wait after the last change before checking again, ms: short for the projects people draw by
 * hand (the list feels live, ~100 ms after an edit), longer for very large ones, where sending
 * the project to the checker costs the page a few milliseconds and typing bursts should pass first. */
export const CHECK_DELAY_MS = 30;
export const LARGE_CHECK_DELAY_MS = 150;
/** Projects with more elements than this count as large. */
const LARGE_PROJECT = 2000;
/** Longest wait for an idle moment after the quiet time, ms (long only while the page is busy). */
const IDLE_TIMEOUT_MS = 250;
const LARGE_IDLE_TIMEOUT_MS = 1000;

/** How long to wait before checking this project version. */
export function checkTiming(project: Project): { delayMs: number; idleTimeoutMs: number } {
  let elements = 0;
  for (const pou of project.pous) for (const n of pou.networks) elements += n.elements.length;
  return elements > LARGE_PROJECT
    ? { delayMs: LARGE_CHECK_DELAY_MS, idleTimeoutMs: LARGE_IDLE_TIMEOUT_MS }
    : { delayMs: CHECK_DELAY_MS, idleTimeoutMs: IDLE_TIMEOUT_MS };
}

const NONE: readonly Diagnostic[] = [];

/** The diagnostics of the latest checked version of the open project (empty until the first check). */
export function useDiagnostics(): readonly Diagnostic[] {
  return useCheckedDiagnostics().diagnostics;
}

/**
 * The diagnostics of the latest checked version and whether any version was checked yet (after a
 * reload the first check takes a moment: "Checking…", not "No problems").
 */
export function useCheckedDiagnostics(): { readonly diagnostics: readonly Diagnostic[]; readonly checked: boolean } {
  const project = useDocument(selectProject);
  const [shown, setShown] = useState<{ project: Project | undefined; diagnostics: readonly Diagnostic[] }>({
    project: undefined,
    diagnostics: NONE,
  });
  useEffect(() => {
    if (shown.project === project) return undefined;
    const take = () => {
      const diagnostics = checkedDiagnostics(project);
      if (diagnostics) setShown({ project, diagnostics });
      return diagnostics !== undefined;
    };
    if (take()) return undefined;
    const unsubscribe = onChecked(take);
    // After the quiet time, wait for an idle moment so sending the project never costs a frame.
    let cancelIdle: (() => void) | undefined;
    const timing = checkTiming(project);
    const timer = setTimeout(() => {
      cancelIdle = whenIdle(() => requestCheck(project), timing.idleTimeoutMs);
    }, timing.delayMs);
    return () => {
      clearTimeout(timer);
      cancelIdle?.();
      unsubscribe();
    };
  }, [project, shown.project]);
  return { diagnostics: shown.diagnostics, checked: shown.project !== undefined };
}

/** Diagnostics of one POU grouped by network index, for cell markers on the canvas. */
export function useDiagnosticsByNetwork(
  pouName: string | undefined,
): ReadonlyMap<number, readonly Diagnostic[]> {
  const diagnostics = useDiagnostics();
  return useMemo(() => {
    const byNetwork = new Map<number, Diagnostic[]>();
    for (const d of diagnostics) {
      if (d.pou !== pouName || d.network < 0) continue;
      const list = byNetwork.get(d.network);
      if (list) list.push(d);
      else byNetwork.set(d.network, [d]);
    }
    return byNetwork;
  }, [diagnostics, pouName]);
}
