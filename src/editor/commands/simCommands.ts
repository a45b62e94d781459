// The simulator's commands with their keys, as CODESYS has them: F5 run, Shift+F5 stop, F9 toggles
// a breakpoint on the network at the cursor (in the ST editor: on the cursor line), F10 / F11 /
// Shift+F11 step over / into / out, Ctrl+F7 writes and F7
// forces the prepared values of the watch table, Alt+F8 applies the edits kept back (apply on request). They run through the toolbar's commands (aware of
// attached hardware), which SimKeysHost (useSimKeys) hands over while the app is mounted.
import type { Project } from '../../model/project';
import type { SimState, SimStore } from '../../store/simState';
import type { SimCommands } from '../hardware/useHardwareStepping';
import { forcePrepared, preparedMessage, preparedValues, writePrepared } from '../sim/preparedValues';
import type { EditorContext } from './editorActions';
import { focusedStLine, toggleLineBreakpoint } from '../st/debug/stDebug';

/** The running app's simulator: its store, the toolbar's commands and the document's project. */
export const simControls: { current?: { sim: SimStore; commands: SimCommands; project(): Project } } = {};

export interface SimCommand {
  readonly id: string;
  readonly label: string;
  readonly group: 'Simulation';
  readonly keys?: readonly string[];
  readonly description: string;
  run(ctx: EditorContext): void;
  enabled?(ctx: EditorContext): boolean;
  /** Why the command cannot run now (undefined when it can). */
  disabledReason?(ctx: EditorContext): string | undefined;
}

const mode = () => simControls.current?.sim.getState().mode;
const notMounted = 'The simulator is not ready yet.';

/** Why Apply changes has nothing to do: said as it is (an edit with errors in apply-as-you-edit is not "the program shown"). */
function unappliedNone(s: Pick<SimState, 'onlineMode' | 'live' | 'runningProgram'>): string {
  if (!s.live || s.runningProgram === null) return 'Nothing is running: Run starts the program shown.';
  if (s.onlineMode !== 'request')
    return 'Edits are applied as you make them (Online change: apply as you edit, in the Project inspector); an edit with errors is not applied until it is fixed.';
  return 'The running program is the one shown: nothing to apply.';
}

/** Why Run / Step cannot start now. */
const cannotStart = (): string | undefined =>
  !simControls.current ? notMounted : mode() === 'running' ? 'The program is already running.' : mode() === 'faulted' ? 'The program faulted: reset it first.' : undefined;

/** The network a breakpoint goes on: the keyboard cursor's, else the selection's. */
const cursorNetwork = (ctx: EditorContext) => {
  const ui = ctx.ui.getState();
  return ui.cursor?.network ?? ui.selection.network;
};

const withReason = (reason: (ctx: EditorContext) => string | undefined) => ({
  enabled: (ctx: EditorContext) => reason(ctx) === undefined,
  disabledReason: reason,
});

export const SIM_COMMANDS: readonly SimCommand[] = [
  {
    id: 'sim.run',
    label: 'Run',
    group: 'Simulation',
    keys: ['f5'],
    description: 'Compile the document and scan in real time',
    run: () => simControls.current?.commands.run(),
    ...withReason(cannotStart),
  },
  {
    id: 'sim.stop',
    label: 'Stop (pause after the current scan)',
    group: 'Simulation',
    keys: ['shift+f5'],
    description: 'Stop scanning after the current scan; values are kept (Reset restarts them)',
    run: () => simControls.current?.sim.getState().pause(),
    ...withReason(() => (!simControls.current ? notMounted : mode() === 'running' ? undefined : 'The program is not running.')),
  },
  {
    id: 'sim.toggleBreakpoint',
    label: 'Toggle breakpoint on the network or ST line',
    group: 'Simulation',
    keys: ['f9'],
    description: 'Set or clear a breakpoint on the network at the cursor, or in the ST editor on the cursor line: execution stops before it runs',
    run: (ctx) => {
      // In the ST editor: the statement on the cursor line.
      const st = focusedStLine();
      if (st) {
        const on = toggleLineBreakpoint(st.view, st.line);
        if (on) ctx.ui.getState().setStatus(`Breakpoint toggled on line ${st.line}: execution stops before its statement, in every instance.`);
        return;
      }
      const network = cursorNetwork(ctx);
      const controls = simControls.current;
      if (!network || !controls) return;
      controls.sim.getState().toggleBreakpoint(network);
      const on = controls.sim.getState().breakpoints.includes(network);
      ctx.ui.getState().setStatus(on ? 'Breakpoint set: execution stops before this network.' : 'Breakpoint cleared.');
    },
    ...withReason((ctx) => (!simControls.current ? notMounted : focusedStLine() || cursorNetwork(ctx) ? undefined : 'Place the cursor on a network or an ST line first.')),
  },
  {
    id: 'sim.stepOver',
    label: 'Step over (network or ST statement)',
    group: 'Simulation',
    keys: ['f10'],
    description: 'The next network runs whole, calls included',
    run: () => simControls.current?.commands.step({ kind: 'network' }),
    ...withReason(cannotStart),
  },
  {
    id: 'sim.stepInto',
    label: 'Step into',
    group: 'Simulation',
    keys: ['f11'],
    description: "A call of a function block or function stops before its body's first network or statement",
    run: () => simControls.current?.commands.step({ kind: 'network', into: true }),
    ...withReason(cannotStart),
  },
  {
    id: 'sim.stepOut',
    label: 'Step out',
    group: 'Simulation',
    keys: ['shift+f11'],
    description: "The rest of the function block's or function's body runs; execution stops at the caller's next network or statement",
    run: () => simControls.current?.commands.step({ kind: 'network', out: true }),
    ...withReason(() => (cannotStart() ?? (simControls.current!.sim.getState().position.length < 2 ? 'Execution is not inside a called body.' : undefined))),
  },
  {
    id: 'sim.stepScan',
    label: 'Step one scan',
    group: 'Simulation',
    description: 'Run one scan (PLC time advances by one cycle)',
    run: () => simControls.current?.commands.step({ kind: 'scans', scans: 1 }),
    ...withReason(cannotStart),
  },
  {
    id: 'sim.applyChanges',
    label: 'Apply changes…',
    group: 'Simulation',
    keys: ['alt+f8'],
    description: 'Apply on request: list the edits not yet in the running program, then apply them at a scan boundary',
    run: () => {
      const controls = simControls.current;
      if (controls && controls.sim.getState().onlineChange?.kind !== 'confirm') controls.sim.getState().applyChanges(controls.project());
    },
    ...withReason(() =>
      !simControls.current
        ? notMounted
        : !simControls.current.sim.getState().unapplied
          ? unappliedNone(simControls.current.sim.getState())
          : simControls.current.sim.getState().onlineChange?.kind === 'confirm'
            ? 'The change list is open: confirm or cancel it.'
            : undefined,
    ),
  },
  {
    id: 'sim.writeValues',
    label: 'Write values',
    group: 'Simulation',
    keys: ['mod+f7'],
    description: 'Write every prepared value of the watch table once',
    run: (ctx) => {
      const controls = simControls.current;
      if (controls) ctx.ui.getState().setStatus(preparedMessage('Wrote', writePrepared(controls.sim)));
    },
    ...withReason(() => (!simControls.current ? notMounted : preparedValues.getState().values.size === 0 ? 'No prepared values: type one in the Watch table first.' : undefined)),
  },
  {
    id: 'sim.forceValues',
    label: 'Force values',
    group: 'Simulation',
    keys: ['f7'],
    description: 'Force every prepared value of the watch table: it keeps that value whatever the program does',
    run: (ctx) => {
      const controls = simControls.current;
      if (controls) ctx.ui.getState().setStatus(preparedMessage('Forced', forcePrepared(controls.sim)));
    },
    ...withReason(() => (!simControls.current ? notMounted : preparedValues.getState().values.size === 0 ? 'No prepared values: type one in the Watch table first.' : undefined)),
  },
  {
    id: 'sim.unforceAll',
    label: 'Remove all forces',
    group: 'Simulation',
    description: 'Every forced variable follows the program again',
    run: () => simControls.current?.sim.getState().unforceAll(),
    ...withReason(() => (!simControls.current ? notMounted : simControls.current.sim.getState().forced.size === 0 ? 'Nothing is forced.' : undefined)),
  },
  {
    id: 'sim.reset',
    label: 'Reset (cold restart)',
    group: 'Simulation',
    description: 'Every variable to its initial value',
    run: () => simControls.current?.commands.reset(),
    ...withReason(() => (!simControls.current ? notMounted : undefined)),
  },
  {
    id: 'sim.clearBreakpoints',
    label: 'Remove all breakpoints',
    group: 'Simulation',
    description: 'Execution no longer stops at any network',
    run: () => simControls.current?.sim.getState().clearBreakpoints(),
    ...withReason(() =>
      !simControls.current
        ? notMounted
        : simControls.current.sim.getState().breakpoints.length === 0 && simControls.current.sim.getState().lineBreakpoints.length === 0
          ? 'No breakpoints are set.'
          : undefined,
    ),
  },
];
