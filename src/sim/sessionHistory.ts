// The session's scan history as the page asks for it: the recorded range, a recorded scan's view,
// finding a change or a condition, "Why?" explanations, and trace or scenario exports (issue 14).
import type { Plc, TextTarget } from '../engine/api';
import type { Project } from '../model/project';
import type { HistoryRecorder } from './historyRecorder';
import { isProgramView } from './layout';
import type { HostMessage, SimFrame, SimLayout, WorkerMessage } from './protocol';
import { plantRecording, scenarioRecordingProblem, type RecordedPlant, type SinceColdStart } from './scenarioRecording';

/** The history requests a session answers with answerHistory. */
export type HistoryRequest = Extract<HostMessage, { type: 'historySeek' | 'historyFind' | 'explain' | 'historyExport' }>;

/** What the session's history answers need from it. */
export interface HistoryContext {
  readonly recorder: HistoryRecorder | undefined;
  readonly plc: Plc | undefined;
  readonly layout: SimLayout | undefined;
  /** The document the running program was compiled from. */
  readonly project: Project | undefined;
  readonly sinceColdStart: SinceColdStart;
  readonly cycleMs: number;
  /** The shown body when it is ST/IL: a recorded scan's view carries what it did. */
  readonly text?: TextTarget | undefined;
  /** The machine the program runs against, if any: a recorded scenario runs against it too. */
  readonly plant?: RecordedPlant | undefined;
  post(message: WorkerMessage, transfer?: Transferable[]): void;
}

/** The recorded scans, as a frame reports them. */
export function historyRange(recorder: HistoryRecorder | undefined): SimFrame['history'] {
  const h = recorder?.history;
  return h && h.first !== undefined ? { first: h.first, last: h.last!, bytes: h.bytes } : undefined;
}

function requireHistory(recorder: HistoryRecorder | undefined): HistoryRecorder {
  if (!recorder || recorder.history.first === undefined) throw new Error('no scan is recorded yet: run or step the program first');
  return recorder;
}

function postHistoryView(ctx: HistoryContext, scan: number): void {
  // Another body monitored (an FB instance, a function) shows its call's power flow in that scan.
  const shown = ctx.layout && !isProgramView(ctx.layout) ? ctx.layout : undefined;
  const view = requireHistory(ctx.recorder).view(scan, shown, ctx.layout, ctx.text);
  if (!view) {
    const h = ctx.recorder!.history;
    throw new Error(`scan ${scan} is not in the history (scans ${h.first} to ${h.last} are recorded)`);
  }
  ctx.post({ type: 'historyView', view }, [view.elements.buffer, view.vlinks.buffer, view.executed.buffer]);
}

/** Answers the page's history requests: show a scan, find a change or a condition, "Why?", export. */
export function answerHistory(m: HistoryRequest, ctx: HistoryContext): void {
  switch (m.type) {
    case 'historySeek':
      postHistoryView(ctx, m.scan);
      return;
    case 'historyFind': {
      const recorder = requireHistory(ctx.recorder);
      const found = m.change !== undefined ? recorder.findChange(m.change, m.from, m.direction) : recorder.findCondition(m.condition ?? '', m.from, m.direction);
      if (found === undefined) {
        const what = m.change !== undefined ? `no ${m.direction > 0 ? 'later' : 'earlier'} change of ${m.change}` : `${m.condition} does not hold in any ${m.direction > 0 ? 'later' : 'earlier'} recorded scan`;
        ctx.post({ type: 'historyNotFound', message: `${what} (scans ${recorder.history.first} to ${recorder.history.last} are recorded)` });
        return;
      }
      postHistoryView(ctx, found);
      return;
    }
    case 'explain': {
      const forced = new Set([...(ctx.plc?.forced().keys() ?? [])].map((n) => n.toUpperCase()));
      const shown = ctx.layout && !isProgramView(ctx.layout) ? ctx.layout.view : undefined;
      const explanation = requireHistory(ctx.recorder).explain(
        m.scan,
        m.target,
        forced,
        ctx.project ? { project: ctx.project, ...(shown ? { shown } : {}) } : undefined,
      );
      if (!explanation) throw new Error(`scan ${m.scan} is not in the history`);
      ctx.post({ type: 'explanation', id: m.id, explanation });
      return;
    }
    case 'historyExport': {
      const recorder = requireHistory(ctx.recorder);
      let refused = m.format === 'scenario' ? scenarioRecordingProblem(ctx.sinceColdStart, recorder, m.from) : undefined;
      // Against a machine: its controls and faults are the scenario's columns, its sensors not inputs to set.
      const plant = m.format === 'scenario' && !refused && ctx.plant ? plantRecording(ctx.plant, ctx.layout, m.inputs ?? [], recorder.recordedRange(m.from, m.to)) : undefined;
      if (plant && 'problem' in plant) refused = plant.problem;
      if (refused) {
        ctx.post({ type: 'historyText', id: m.id, format: m.format, text: '', refused });
        return;
      }
      const text =
        m.format === 'trace'
          ? recorder.traceCsv(m.names ?? ctx.layout!.variables.map((v) => v.name), m.from, m.to)
          : plant && !('problem' in plant)
            ? recorder.scenarioCsv(plant.inputs, m.outputs ?? [], ctx.cycleMs, m.from, m.to, plant.columns)
            : recorder.scenarioCsv(m.inputs ?? [], m.outputs ?? [], ctx.cycleMs, m.from, m.to);
      ctx.post({ type: 'historyText', id: m.id, format: m.format, text });
      return;
    }
  }
}
