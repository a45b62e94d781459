// Simulation state for the UI: mirrors the worker's frames and sends its commands.
// Nothing here enters the document or its undo history (STYLE.md: simulation values and forced
// I/O never enter the history).
//
// One store per editor, `createSimStore(transport)`; components read it with `useSim(selector)`
// (src/editor/sim/simContext.ts) through narrow selectors. Commands that run the program take the
// current document, which is compiled first when it changed since the last command.
import { createStore } from 'zustand';
import type { Value } from '../model/iecTypes';
import type { Project } from '../model/project';
import type { SimTransport } from '../sim/host';
import { programId } from '../sim/programId';
import { changeList } from '../sim/changeList';
import { diffProject, type ProjectDelta } from '../sim/projectDelta';
import type { HistoryView, HostMessage, LineBreakpoint, SimFrame, SimLayout, TrendSamples, WorkerMessage } from '../sim/protocol';
import type { Explanation } from '../engine/explain';
import type { ScenarioResult } from '../sim/scenario';
import { appendTrend, emptyTrend } from '../sim/trendBuffer';
import { DEFAULT_HISTORY_SCANS } from '../sim/history';
import { scopeFor, viewKey, type CanvasScope } from '../sim/scope';
import type { SimState, SimStore, SimValueGuard } from './simState';

export const DEFAULT_CYCLE_MS = 10;
export const DEFAULT_TREND_SCANS = 500;
/** The trend's longest window: the scan history's default length (src/sim/history.ts). */
export const MAX_TREND_SCANS = DEFAULT_HISTORY_SCANS;

const sameName = (a: string, b: string) => a.toUpperCase() === b.toUpperCase();
/**
 * The same watched or trended name: in any case, but a machine's names (`tank.Pump`, the contactor,
 * and `tank.pump`, the speed) are told apart by their spelling (src/plant/values.ts).
 */
const sameWatched = (plant: string | undefined) => (a: string, b: string) =>
  a === b || (sameName(a, b) && !(plant !== undefined && a.toLowerCase().startsWith(`${plant}.`)));

interface SentDocument {
  readonly project: Project;
  /** Its programId: what the worker reports when it runs this document. */
  readonly id: string;
  /** Sent with Run/Step ('start': a refusal stops the worker) or as an online edit ('load'). */
  readonly by: 'start' | 'load';
}

export function createSimStore(transport: SimTransport): SimStore {
  // What runs is always what is shown:
  // - `sentProject` is the document the worker confirmed it installed ('compiled' ok, or a frame of
  //   the current epoch running it); only then is a Run without the document trusted. Any refusal,
  //   error or unload clears it, so the next Run sends the document again.
  // - `expected` are the programs the store accepts as the one shown: the document of the last
  //   Run/Step, and during an online change also the program still running until the swap (or
  //   kept running because the edit has errors). A frame of the current epoch from any other program
  //   is never shown as running: the store stops the worker and says why. Its outputs never reach
  //   the gateway.
  let sentProject: SentDocument | undefined;
  let requestedDoc: SentDocument | undefined;
  /** The last documents sent, by programId: what a frame's program is, for runningProject. */
  const sentDocs = new Map<string, Project>();
  const remember = (doc: SentDocument | undefined) => {
    if (!doc) return;
    sentDocs.delete(doc.id);
    sentDocs.set(doc.id, doc.project);
    while (sentDocs.size > 6) sentDocs.delete(sentDocs.keys().next().value!);
  };
  // Every document sent is remembered (a setter would hide the assignments below).
  const track = {
    get requested() {
      return requestedDoc;
    },
    set requested(doc: SentDocument | undefined) {
      requestedDoc = doc;
      remember(doc);
    },
  };
  let expectedSet = new Set<string>();
  /** The programs whose outputs may drive the hardware; the worker is told (gwPrograms: it drives the link). */
  const expected = {
    has: (id: string) => expectedSet.has(id),
    set(ids: Set<string>) {
      expectedSet = ids;
      transport.send({ type: 'gwPrograms', ids: [...ids] });
    },
  };
  /** The program the worker last reported (current epoch), null when none. */
  let running: string | null = null;
  let epoch = 0;
  const outputListeners = new Set<(outputs: Readonly<Record<string, Value>>, scan: number) => void>();
  /** Requests answered by id (history export, scenario replay, explanations). */
  let requestIds = 0;
  const pending = new Map<number, { resolve: (value: never) => void; reject: (error: Error) => void }>();
  const request = <T,>(make: (id: number) => HostMessage): Promise<T> =>
    new Promise<T>((resolve, reject) => {
      const id = ++requestIds;
      pending.set(id, { resolve: resolve as (value: never) => void, reject });
      transport.send(make(id));
    });
  /** The live power and values while a recorded scan is shown, to put back on Live. */
  let liveStash: Pick<SimState, 'elements' | 'vlinks' | 'executed' | 'values' | 'pins' | 'text'> | undefined;
  const send = (message: HostMessage) => transport.send(message);
  /**
   * The last document sent to the worker: the next one goes as a difference from it (only what an
   * edit replaced travels). Forgotten when the worker may have lost it (an error, a new worker).
   */
  let documentSeq = 0;
  let workerDocument: { readonly seq: number; readonly project: Project } | undefined;
  const packDocument = (project: Project): { project: Project; docSeq: number } | { delta: ProjectDelta; docSeq: number } => {
    const docSeq = ++documentSeq;
    const base = workerDocument;
    workerDocument = { seq: docSeq, project };
    return base ? { delta: diffProject(base.project, base.seq, project), docSeq } : { project, docSeq };
  };

  /** The document to send with Run/Step unless the worker confirmed it runs this very program. */
  const fresh = (project: Project): Project | undefined => {
    const id = programId(project);
    // Apply on request: Run and Step go on with the running program; only Apply puts the edits in.
    if (store.getState().onlineMode === 'request' && store.getState().live && running !== null && running !== id && sentDocs.has(running)) return undefined;
    // A Run/Step with a changed document on a live program is an online change: the running program
    // finishes its scan and is swapped at the boundary; otherwise only this document may run.
    expected.set(new Set(store.getState().live && running !== null ? [id, running] : [id]));
    if (sentProject?.id === id && running === id) return undefined;
    track.requested = { project, id, by: 'start' };
    return project;
  };
  const nextEpoch = () => ++epoch;
  // Breakpoints go by network id: the worker finds them in every POU of the program it runs.
  const sendBreakpoints = () => {
    const { layout, breakpoints, lineBreakpoints } = store.getState();
    if (!layout) return;
    send({ type: 'setBreakpoints', ids: breakpoints, lines: lineBreakpoints });
  };
  /** A step or Run was asked: the next stop (a step's end, a breakpoint) is followed by the editor. */
  let followNext = false;
  let lastStopKey = '';
  /** The view last asked of the worker. */
  let sentView = '';
  /** Works out the canvas scope from the layout, the shown POU and the picked instance; asks the worker for that body's power. */
  const updateScope = () => {
    const { layout, shownPou, picked, canvasScope } = store.getState();
    const scope = scopeFor(layout, shownPou, shownPou ? picked.get(shownPou.name.toUpperCase()) : undefined);
    if (!sameScope(scope, canvasScope)) store.setState({ canvasScope: scope });
    if (!layout || !scope) return;
    const key = viewKey(scope.view);
    if (key === viewKey(layout.view) || key === sentView) return;
    sentView = key;
    send({ type: 'setView', view: scope.view });
  };
  /** Armings of the trend trigger so far (frames of an earlier one are told apart). */
  let trendArms = 0;
  const sendTrend = () => {
    const { trendNames, trendCapacity, trendTrigger } = store.getState();
    send({ type: 'setTrend', names: trendNames, capacity: trendCapacity, ...(trendTrigger ? { trigger: trendTrigger } : {}) });
  };

  /** Holds writes and forces that must be confirmed first (a field output of attached hardware). */
  let valueGuard: SimValueGuard | undefined;
  const store: SimStore = createStore<SimState>()((set, get) => {
    const currentValue = (name: string): Value | undefined => {
      const i = get().variableIndex.get(name.toUpperCase());
      return i === undefined ? undefined : get().values[i];
    };

    return {
      mode: 'stopped',
      scan: 0,
      timeMs: 0,
      cycleMs: DEFAULT_CYCLE_MS,
      exec: { lastMs: 0, avgMs: 0, maxMs: 0 },
      fault: undefined,
      nextNetwork: -1,
      breakpointHit: undefined,
      breakpointAt: undefined,
      position: [],
      stopSeq: 0,
      stop: undefined,
      shownPou: undefined,
      picked: new Map(),
      canvasScope: undefined,
      overruns: 0,
      layout: undefined,
      live: false,
      elementIndex: new Map(),
      vlinkIndex: new Map(),
      variableIndex: new Map(),
      elements: new Uint8Array(0),
      vlinks: new Uint8Array(0),
      executed: new Uint8Array(0),
      values: [],
      pins: [],
      forced: new Map(),
      breakpoints: [],
      lineBreakpoints: [],
      text: undefined,
      watch: [],
      trendNames: [],
      trendCapacity: DEFAULT_TREND_SCANS,
      trend: emptyTrend([]),
      trendTrigger: undefined,
      trendTriggerState: undefined,
      trendCapture: undefined,
      refusal: undefined,
      notice: undefined,
      contextMenu: undefined,
      onlineChange: undefined,
      onlineConfirmRequired: false,
      onlineMode: 'edit',
      runningProject: undefined,
      runningProgram: null,
      unapplied: undefined,
      history: undefined,
      historyScan: undefined,
      historyTimeMs: undefined,
      historyMessage: undefined,
      explanation: undefined,
      plant: undefined,
      plantAtScan: undefined,

      run: (project) => {
        followNext = true;
        set({ refusal: undefined, notice: undefined });
        send({ type: 'run', ...withProject(fresh(project)), epoch: nextEpoch() });
      },
      pause: () => send({ type: 'pause' }),
      step: (project, scans) => {
        followNext = true;
        set({ refusal: undefined, notice: undefined });
        send({ type: 'step', scans, ...withProject(fresh(project)), epoch: nextEpoch() });
      },
      stepNetwork: (project, into, out) => {
        followNext = true;
        set({ refusal: undefined, notice: undefined });
        send({ type: 'stepNetwork', ...(into ? { into: true } : {}), ...(out ? { out: true } : {}), ...withProject(fresh(project)), epoch: nextEpoch() });
      },
      showPou: (pou) => {
        const shown = get().shownPou;
        if (shown?.name === pou?.name && shown?.kind === pou?.kind) return;
        set({ shownPou: pou });
        updateScope();
      },
      pickInstance: (pou, instance) => {
        const picked = new Map(get().picked);
        picked.set(pou.toUpperCase(), instance);
        set({ picked });
        updateScope();
      },
      reset: () => {
        set({ notice: undefined, trend: emptyTrend(get().trendNames) });
        send({ type: 'reset' });
      },
      unload: () => {
        sentProject = undefined;
        track.requested = undefined;
        expected.set(new Set());
        running = null;
        set({
          notice: undefined,
          refusal: undefined,
          live: false,
          layout: undefined,
          elementIndex: new Map(),
          vlinkIndex: new Map(),
          variableIndex: new Map(),
          breakpoints: [],
          lineBreakpoints: [],
          text: undefined,
          trend: emptyTrend(get().trendNames),
          runningProject: undefined,
          runningProgram: null,
          unapplied: undefined,
        });
        sentDocs.clear();
        send({ type: 'setBreakpoints', networks: [] });
        // The worker drops the program (and its forces): nothing of the previous project runs on.
        send({ type: 'unload', epoch: nextEpoch() });
      },
      warmRestart: () => {
        set({ notice: undefined });
        send({ type: 'warmRestart' });
      },
      setCycle: (cycleMs) => {
        set({ cycleMs });
        send({ type: 'setCycle', cycleMs });
      },
      documentChanged: (project) => {
        if (!get().layout) return;
        const id = programId(project);
        if (id === track.requested?.id) return;
        track.requested = { project, id, by: 'load' };
        // Online change: the running program stays accepted until the swap (or while the edit has errors).
        expected.set(new Set(running === null ? [id] : [id, running]));
        send({ type: 'load', ...packDocument(project), epoch: nextEpoch() });
      },
      toggleBreakpoint: (networkId) => {
        const { breakpoints } = get();
        set({ breakpoints: breakpoints.includes(networkId) ? breakpoints.filter((b) => b !== networkId) : [...breakpoints, networkId] });
        sendBreakpoints();
      },
      toggleLineBreakpoint: (pou, line, instance) => {
        const key = (b: LineBreakpoint) => `${b.pou.toUpperCase()}|${b.line}|${(b.instance ?? '').toUpperCase()}`;
        const bp: LineBreakpoint = { pou, line, ...(instance ? { instance } : {}) };
        const list = get().lineBreakpoints;
        const on = list.some((b) => key(b) === key(bp));
        set({ lineBreakpoints: on ? list.filter((b) => key(b) !== key(bp)) : [...list, bp] });
        sendBreakpoints();
      },
      clearBreakpoints: () => {
        set({ breakpoints: [], lineBreakpoints: [] });
        sendBreakpoints();
      },
      write: (name, input) => {
        const go = () => send({ type: 'write', name, input });
        if (!valueGuard?.({ kind: 'write', name, input }, go)) go();
      },
      force: (name, input) => {
        const go = () => send({ type: 'force', name, input });
        if (!valueGuard?.({ kind: 'force', name, input }, go)) go();
      },
      setValueGuard: (guard) => {
        valueGuard = guard;
      },
      unforce: (name) => send({ type: 'unforce', name }),
      unforceAll: () => send({ type: 'unforceAll' }),
      toggleInput: (name) => send({ type: 'write', name, input: { value: currentValue(name) !== true } }),
      pressInput: (name) => send({ type: 'write', name, input: { value: true } }),
      releaseInput: (name) => send({ type: 'write', name, input: { value: false } }),
      addWatch: (name) => {
        const same = sameWatched(get().plant?.id);
        if (get().watch.some((w) => same(w, name))) return;
        set({ watch: [...get().watch, name] });
      },
      removeWatch: (name) => {
        const same = sameWatched(get().plant?.id);
        set({ watch: get().watch.filter((w) => !same(w, name)) });
      },
      toggleTrend: (name) => {
        const { trendNames } = get();
        const same = sameWatched(get().plant?.id);
        const next = trendNames.some((n) => same(n, name)) ? trendNames.filter((n) => !same(n, name)) : [...trendNames, name];
        set({ trendNames: next, trend: emptyTrend(next), trendCapture: undefined });
        sendTrend();
      },
      setTrendCapacity: (scans) => {
        const capacity = Math.max(10, Math.min(MAX_TREND_SCANS, Math.floor(scans)));
        set({ trendCapacity: capacity, trend: emptyTrend(get().trendNames), trendCapture: undefined });
        sendTrend();
      },
      setTrendTrigger: (trigger) => {
        set({ trendTrigger: trigger && { ...trigger, arm: ++trendArms }, trendCapture: undefined, trendTriggerState: trigger ? 'armed' : undefined });
        sendTrend();
      },
      armTrendTrigger: () => {
        const trigger = get().trendTrigger;
        if (!trigger) return;
        set({ trendTrigger: { ...trigger, arm: ++trendArms }, trendCapture: undefined, trendTriggerState: 'armed' });
        sendTrend();
      },
      openContextMenu: (menu) => set({ contextMenu: menu }),
      closeContextMenu: () => set({ contextMenu: undefined }),
      dismissNotice: () => set({ notice: undefined, refusal: undefined }),
      setOnlineConfirmRequired: (required) => {
        if (required === get().onlineConfirmRequired) return;
        set({ onlineConfirmRequired: required });
        send({ type: 'setOnlineConfirm', required });
      },
      answerOnlineChange: (apply) => {
        const change = get().onlineChange;
        if (change?.kind !== 'confirm') return;
        send({ type: 'confirmOnline', id: change.id, apply });
        // Cancelled: the worker was asked for nothing that runs; the document is sent again when it is applied.
        if (!apply) track.requested = undefined;
        set({ onlineChange: apply ? { kind: 'pending', id: change.id, plan: change.plan } : { kind: 'cancelled', id: change.id } });
      },
      dismissOnlineChange: () => set({ onlineChange: undefined }),
      setOnlineMode: (mode) => {
        if (mode !== get().onlineMode) set({ onlineMode: mode });
      },
      setUnapplied: (unapplied) => set({ unapplied }),
      applyChanges: (project) => {
        if (!get().layout) return;
        const id = programId(project);
        track.requested = { project, id, by: 'load' };
        // As an edit applied as made: the running program stays accepted until the swap (or a Cancel).
        expected.set(new Set(running === null ? [id] : [id, running]));
        send({ type: 'load', ...packDocument(project), epoch: nextEpoch(), confirm: true });
      },
      setInputs: (values) => send({ type: 'setInputs', values }),
      setPlant: (plant) => send({ type: 'setPlant', plant }),
      plantOperator: (name, value) => send({ type: 'plantOperator', name, value }),
      plantFault: (id, active) => send({ type: 'plantFault', id, active }),
      seekHistory: (scan) => {
        const h = get().history;
        if (!h) return;
        set({ historyMessage: undefined });
        send({ type: 'historySeek', scan: Math.max(h.first, Math.min(h.last, Math.round(scan))) });
      },
      goLive: () => {
        if (liveStash) set({ ...liveStash });
        liveStash = undefined;
        // An explanation is about the scan that was viewed: its tags and text go with it.
        set({ historyScan: undefined, historyTimeMs: undefined, historyMessage: undefined, explanation: undefined, plantAtScan: undefined });
      },
      findChange: (name, direction) => {
        const from = get().historyScan ?? get().history?.last;
        if (from === undefined) return;
        set({ historyMessage: undefined });
        send({ type: 'historyFind', from, direction, change: name });
      },
      findCondition: (expression, direction) => {
        const from = get().historyScan ?? (direction > 0 ? get().history?.first : get().history?.last);
        if (from === undefined) return;
        set({ historyMessage: undefined });
        send({ type: 'historyFind', from: get().historyScan === undefined && direction > 0 ? from - 1 : from, direction, condition: expression });
      },
      explain: (target, scan) => {
        const at = scan ?? get().historyScan ?? get().history?.last;
        if (at === undefined) {
          set({ historyMessage: 'Nothing is recorded yet: run or step the program, then ask Why?' });
          return;
        }
        request<Explanation>((id) => ({ type: 'explain', id, scan: at, target })).then(
          (explanation) => set({ explanation }),
          (error: Error) => set({ historyMessage: error.message }),
        );
      },
      closeExplanation: () => set({ explanation: undefined }),
      setHistoryDepth: (maxScans, budgetBytes) => send({ type: 'setHistory', maxScans, budgetBytes }),
      exportHistory: (r) =>
        request<string>((id) => ({
          type: 'historyExport',
          id,
          format: r.format,
          ...(r.names ? { names: r.names } : {}),
          ...(r.inputs ? { inputs: r.inputs } : {}),
          ...(r.outputs ? { outputs: r.outputs } : {}),
        })),
      replayScenario: (project, scenario) => {
        sentProject = undefined;
        expected.set(new Set([programId(project)]));
        track.requested = { project, id: programId(project), by: 'start' };
        liveStash = undefined;
        set({ historyScan: undefined, historyTimeMs: undefined, explanation: undefined, refusal: undefined, notice: undefined });
        const docSeq = ++documentSeq;
        workerDocument = { seq: docSeq, project };
        return request<ScenarioResult>((id) => ({ type: 'replayScenario', id, project, scenario, epoch: nextEpoch(), docSeq }));
      },
      onOutputs: (listener) => {
        outputListeners.add(listener);
        if (outputListeners.size === 1) send({ type: 'subscribeOutputs', enabled: true });
        return () => {
          outputListeners.delete(listener);
          if (outputListeners.size === 0) send({ type: 'subscribeOutputs', enabled: false });
        };
      },
    };

    function withProject(project: Project | undefined): { project?: Project } | { delta: ProjectDelta; docSeq: number } {
      return project ? packDocument(project) : {};
    }
  });

  transport.listen((message: WorkerMessage) => {
    switch (message.type) {
      case 'compiled':
        if (!message.ok) {
          // Compile this document again next time. An online edit with errors leaves the last good
          // program running; a refused Run/Step dropped the previous program (the worker is stopped).
          sentProject = undefined;
          if (message.online || track.requested?.by === 'load') {
            store.setState({ refusal: { diagnostics: message.diagnostics, online: message.online } });
          } else {
            expected.set(new Set());
            store.setState({ refusal: { diagnostics: message.diagnostics, online: false }, ...NO_PROGRAM });
          }
          return;
        }
        if (message.program !== undefined && message.program === track.requested?.id) {
          sentProject = track.requested;
          expected.set(new Set([message.program]));
        }
        if (message.layout) {
          store.setState({ refusal: undefined, ...indexLayout(message.layout) });
          // Breakpoints are kept by network id; the new program has them where those networks are.
          sendBreakpoints();
          sentView = '';
          updateScope();
        }
        return;
      case 'layout':
        // The monitored body changed: its power comes with the next frame.
        store.setState({ ...indexLayout(message.layout), elements: new Uint8Array(0), vlinks: new Uint8Array(0), executed: new Uint8Array(0) });
        updateScope();
        return;
      case 'frame': {
        const { program } = message.frame;
        if (message.frame.epoch === epoch) {
          running = program;
          const runningProject = program === null ? undefined : sentDocs.get(program);
          if (store.getState().runningProgram !== program || store.getState().runningProject !== runningProject)
            store.setState({ runningProgram: program, runningProject });
          if (program === null) sentProject = undefined;
          else if (program === track.requested?.id && expected.has(program)) sentProject = track.requested;
          if (program !== null && !expected.has(program)) {
            refuseHiddenProgram();
            return;
          }
        } else if (program !== null && !expected.has(program)) {
          return; // in flight from before the last command, and not the program shown: never shown
        }
        let patch = applyFrame(store.getState(), message.frame);
        const viewing = store.getState().historyScan !== undefined;
        const restarted = message.frame.history === undefined;
        if (viewing && !restarted) {
          // A recorded scan is shown: the live state is kept for Live, the view stays frozen.
          const { elements, vlinks, executed, values, pins, text, ...rest } = patch;
          liveStash = { elements: elements!, vlinks: vlinks!, executed: executed!, values: values!, pins: pins!, text };
          patch = rest;
        } else if (viewing) {
          liveStash = undefined;
          patch = { ...patch, historyScan: undefined, historyTimeMs: undefined };
        }
        store.setState({ ...patch, history: message.frame.history, ...followStop(message.frame, message.frame.epoch === epoch) });
        return;
      }
      case 'error':
        // The next Run sends the document again (whole) rather than trusting what the worker has.
        sentProject = undefined;
        workerDocument = undefined;
        if (message.message.startsWith(WORKER_GONE)) {
          // The worker itself is gone (crashed or terminated): nothing runs any more, and the
          // simulation must not show Running (nor drive hardware) for a program that no longer exists.
          // Nothing will answer the requests waiting either.
          for (const p of pending.values()) p.reject(new Error(message.message));
          pending.clear();
          track.requested = undefined;
          running = null;
          expected.set(new Set());
          store.setState({ ...NO_PROGRAM, mode: 'stopped', notice: message.message });
          return;
        }
        store.setState({ notice: message.message });
        return;
      case 'historyView': {
        const state = store.getState();
        if (state.historyScan === undefined) liveStash = { elements: state.elements, vlinks: state.vlinks, executed: state.executed, values: state.values, pins: state.pins, text: state.text };
        store.setState({ ...viewOf(message.view), historyMessage: undefined });
        return;
      }
      case 'historyNotFound':
        store.setState({ historyMessage: message.message });
        return;
      case 'requestFailed': {
        const p = pending.get(message.id);
        pending.delete(message.id);
        p?.reject(new Error(message.message));
        return;
      }
      case 'explanation':
      case 'historyText':
      case 'scenarioReplayed': {
        const p = pending.get(message.id);
        pending.delete(message.id);
        if (message.type === 'historyText' && message.refused !== undefined) {
          p?.reject(new Error(message.refused));
          return;
        }
        const value = message.type === 'explanation' ? message.explanation : message.type === 'historyText' ? message.text : message.result;
        p?.resolve(value as never);
        return;
      }
      case 'outputs':
        // Only the shown program's outputs reach the gateway.
        if (!expected.has(message.program)) return;
        for (const listener of outputListeners) listener(message.outputs, message.scan);
        return;
      case 'ready':
        return;
      case 'onlinePlan': {
        if (!message.confirm) {
          store.setState({ onlineChange: { kind: 'pending', id: message.id, plan: message.plan } });
          return;
        }
        // What the answer decides: the running document against the one sent, change by change.
        const before = store.getState().runningProject;
        const after = track.requested?.project;
        const changes = before && after ? changeList(before, after) : undefined;
        store.setState({ onlineChange: { kind: 'confirm', id: message.id, plan: message.plan, ...(changes ? { changes } : {}) } });
        return;
      }
      case 'onlineApplied':
        store.setState({ onlineChange: { kind: 'applied', id: message.id, scan: message.scan, plan: message.plan } });
        return;
      case 'onlineCancelled':
        store.setState({ onlineChange: { kind: 'cancelled', id: message.id } });
        return;
    }
  });
  // No program any more (unloaded, refused, stopped): no online change is waiting or pending; after
  // a cold restart (scan 0) nothing an online change kept is left, so its confirmation goes too.
  store.subscribe((state) => {
    const kind = state.onlineChange?.kind;
    const gone = !state.layout && (kind === 'confirm' || kind === 'pending');
    const restarted = kind === 'applied' && state.mode === 'stopped' && state.scan === 0;
    if (gone || restarted) store.setState({ onlineChange: undefined });
    if (!state.layout && state.canvasScope) store.setState({ canvasScope: undefined });
  });

  /**
   * A stop the editor follows: after a step (or a Run/Step N that a breakpoint stopped), where
   * execution stands, once per new stop.
   */
  function followStop(frame: SimFrame, current: boolean): Partial<SimState> {
    const at = frame.breakpointAt ?? frame.position?.at(-1);
    const key = at ? `${at.pou}|${at.instance ?? ''}|${at.network}|${at.line ?? ''}` : '';
    if (!current || frame.mode === 'running' || frame.mode === 'stopped') return {};
    const follow = at !== undefined && (followNext || (frame.breakpointAt !== undefined && key !== lastStopKey));
    followNext = false;
    lastStopKey = key;
    return follow ? { stop: at, stopSeq: store.getState().stopSeq + 1 } : {};
  }

  /** The worker runs a program that is not the one shown: stop it, forget it and say so. */
  function refuseHiddenProgram(): void {
    sentProject = undefined;
    track.requested = undefined;
    expected.set(new Set());
    running = null;
    transport.send({ type: 'unload', epoch: nextEpoch() });
    store.setState({
      ...NO_PROGRAM,
      mode: 'stopped',
      notice: 'The simulation was stopped: the simulator was running a program other than the one shown. Press Run to run the program shown.',
    });
  }
  return store;
}

/** How host.ts reports a worker that died (script error, terminated). */
const WORKER_GONE = 'the simulator stopped';

/** The store's state when the worker has no program (refused Run, unload). */
const NO_PROGRAM: Pick<SimState, 'live' | 'layout' | 'elementIndex' | 'vlinkIndex' | 'variableIndex' | 'runningProject' | 'runningProgram'> = {
  live: false,
  runningProject: undefined,
  runningProgram: null,
  layout: undefined,
  elementIndex: new Map(),
  vlinkIndex: new Map(),
  variableIndex: new Map(),
};

function sameScope(a: CanvasScope | undefined, b: CanvasScope | undefined): boolean {
  if (!a || !b) return a === b;
  return viewKey(a.view) === viewKey(b.view) && a.prefix === b.prefix && a.choices.join('\n') === b.choices.join('\n');
}

function viewOf(view: HistoryView): Partial<SimState> {
  return { historyScan: view.scan, historyTimeMs: view.timeMs, elements: view.elements, vlinks: view.vlinks, executed: view.executed, values: view.values, pins: view.pins, text: view.text, plantAtScan: view.plant };
}

function indexLayout(layout: SimLayout): Pick<SimState, 'layout' | 'elementIndex' | 'vlinkIndex' | 'variableIndex'> {
  const elementIndex = new Map<string, number>();
  layout.elementIds.forEach((id, i) => elementIndex.set(id, i));
  const vlinkIndex = new Map<string, number>();
  layout.networkIds.forEach((networkId, n) => {
    for (let i = layout.vlinkOffsets[n]!; i < layout.vlinkOffsets[n + 1]!; i++) vlinkIndex.set(`${networkId}/${layout.vlinkKeys[i]}`, i);
  });
  const variableIndex = new Map<string, number>();
  layout.variables.forEach((v, i) => variableIndex.set(v.name.toUpperCase(), i));
  return { layout, elementIndex, vlinkIndex, variableIndex };
}

function applyFrame(state: SimState, frame: SimFrame): Partial<SimState> {
  const forced = new Map<string, Value>();
  for (const [name, value] of frame.forced) forced.set(name.toUpperCase(), value);
  return {
    mode: frame.mode,
    scan: frame.scan,
    timeMs: frame.timeMs,
    cycleMs: frame.cycleMs,
    exec: frame.exec,
    fault: frame.fault,
    nextNetwork: frame.nextNetwork,
    breakpointHit: frame.breakpointHit,
    breakpointAt: frame.breakpointAt,
    position: frame.position ?? [],
    overruns: frame.overruns,
    live: state.layout !== undefined && (frame.mode !== 'stopped' || frame.scan > 0 || frame.nextNetwork !== -1),
    elements: frame.elements,
    vlinks: frame.vlinks,
    executed: frame.executed,
    values: frame.values,
    pins: frame.pins,
    text: frame.text,
    forced,
    plant: frame.plant,
    ...(frame.trend ? { trend: appendTrend(state.trend, frame.trend as TrendSamples, state.trendCapacity) } : {}),
    ...(frame.mode === 'stopped' && frame.scan === 0 ? { trend: emptyTrend(state.trendNames) } : {}),
    // State and captures of an earlier arming (frames already under way) are left out.
    ...(state.trendTrigger && frame.trendTrigger?.arm === state.trendTrigger.arm ? { trendTriggerState: frame.trendTrigger.state } : {}),
    ...(frame.trendCapture && frame.trendCapture.arm === state.trendTrigger?.arm ? { trendCapture: frame.trendCapture } : {}),
  };
}
