// The project's tasks as a PLC programmer configures them (CODESYS "Task configuration", Beremiz's
// resource): name, cyclic interval or event trigger (a BOOL global), priority, and the program
// instances each task runs, in order;
// what runs in which tick of the simulator (taskSchedule: MATIEC's common tick).
// Every change is checked first (taskProblems) and is one undo step; a refused change keeps the
// field as typed with the reason beside it until it is fixed or the dialog is closed.
import { useLayoutEffect, useRef, useState, type InputHTMLAttributes } from 'react';
import { describeSchedule, taskSchedule } from '../../engine/compile/taskSchedule';
import type { Task } from '../../model/project';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { taskProblems, triggerCandidates, withTrigger, type TaskProblem } from '../../store/taskCommands';
import { ModalDialog } from '../files/ModalDialog';

const int = (text: string) => (/^\s*\d+\s*$/.test(text) ? Number(text) : NaN);
/** An interval as typed: empty is none (0), which only an event task may have. */
const interval = (text: string) => (text.trim() === '' ? 0 : int(text));

export function TasksDialog({ onClose }: { readonly onClose: () => void }) {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  // The list as edited: what the project holds, or a draft that does not pass the checks yet.
  const [draft, setDraft] = useState<readonly Task[] | undefined>(undefined);
  const [message, setMessage] = useState('');
  // The control to give the keyboard to after a change that moved or removed the focused one.
  const focusNext = useRef<string | undefined>(undefined);
  const body = useRef<HTMLDivElement>(null);
  useLayoutEffect(() => {
    const selector = focusNext.current;
    if (!selector) return;
    focusNext.current = undefined;
    body.current?.querySelector<HTMLElement>(selector)?.focus();
  });
  const tasks = draft ?? project.tasks;
  const problems = draft ? taskProblems(project, draft) : [];
  const programs = project.pous.filter((p) => p.kind === 'PROGRAM');
  const triggers = triggerCandidates(project);

  const apply = (next: readonly Task[]) => {
    const refused = store.getState().setTasks(next);
    setDraft(refused ? next : undefined);
    setMessage('');
  };
  const editTask = (ti: number, patch: Partial<Task>) =>
    apply(tasks.map((t, i) => (i === ti ? { ...t, ...patch } : t)));
  const editProgram = (ti: number, pi: number, patch: Partial<Task['programs'][number]>) =>
    editTask(ti, { programs: tasks[ti]!.programs.map((p, i) => (i === pi ? { ...p, ...patch } : p)) });
  const moveProgram = (ti: number, pi: number, by: -1 | 1) => {
    const list = [...tasks[ti]!.programs];
    const [moved] = list.splice(pi, 1);
    list.splice(pi + by, 0, moved!);
    // The keyboard follows the moved instance (its button, or the other one at the end of the list).
    const to = pi + by;
    const edge = (by < 0 && to === 0) || (by > 0 && to === list.length - 1);
    focusNext.current = `[data-testid="task-${ti}-program-${to}"] [data-order="${edge ? -by : by}"]`;
    editTask(ti, { programs: list });
  };
  const problemOf = (ti: number, field: TaskProblem['field'], pi?: number) =>
    problems.find((p) => p.task === ti && p.field === field && p.program === pi)?.message;
  const say = (problem: TaskProblem | undefined) => setMessage(problem?.message ?? '');

  return (
    <ModalDialog
      role="dialog"
      titleId="rs-tasks-title"
      title="Tasks"
      describedBy="rs-tasks-text"
      className="rs-tasks-dialog"
      testId="tasks-dialog"
      onClose={onClose}
      buttons={
        <button type="button" className="rs-button rs-primary" data-testid="tasks-close" onClick={onClose}>
          Close
        </button>
      }
    >
      <p id="rs-tasks-text" className="rs-tree-detail">
        Each cyclic task runs its program instances at its own interval, as MATIEC runs a resource: a scan is
        one tick of the greatest common divisor of the intervals, and a task runs in the ticks that are a
        multiple of its interval. An event task runs its instances in the ticks where its BOOL global rose
        since the last tick (sampled before any program runs); an interval it has only counts in the tick. In
        a tick, the instances run in the order declared (task after task, as listed); the priority goes to the
        PLCopen export and reorders nothing.
      </p>
      <p className="rs-tree-detail" data-testid="tasks-schedule">
        {scheduleText(problems.length === 0 ? tasks : project.tasks)}
      </p>
      <div ref={body} className="rs-tasks-list">
        {tasks.map((t, ti) => (
          // Keyed by position (not content): an edit keeps the keyboard where it is; the fields show
          // what the project (or a refused draft) now holds, an undo included (CommitInput).
          <fieldset key={ti} className="rs-task" data-testid={`task-${ti}`}>
            <legend className="rs-mono">{t.name || '(no name)'}</legend>
            <div className="rs-field">
              <label htmlFor={`task-name-${ti}`}>Name</label>
              <CommitInput
                id={`task-name-${ti}`}
                className="rs-cell-input"
                data-testid={`task-name-${ti}`}
                value={t.name}
                onCommit={(text) => editTask(ti, { name: text.trim() })}
              />
              <label htmlFor={`task-cycle-${ti}`}>Interval (ms)</label>
              <CommitInput
                id={`task-cycle-${ti}`}
                className="rs-cell-input"
                inputMode="numeric"
                data-testid={`task-cycle-${ti}`}
                value={t.single && t.cycleMs === 0 ? '' : String(t.cycleMs)}
                placeholder={t.single ? 'none' : undefined}
                onCommit={(text) => interval(text) !== t.cycleMs && editTask(ti, { cycleMs: interval(text) })}
              />
              <label htmlFor={`task-single-${ti}`}>Runs on rising edge of</label>
              <select
                id={`task-single-${ti}`}
                className="rs-cell-input rs-mono"
                data-testid={`task-single-${ti}`}
                value={t.single ?? ''}
                onChange={(e) => apply(tasks.map((x, i) => (i === ti ? withTrigger(x, e.target.value) : x)))}
              >
                <option value="">(nothing: cyclic)</option>
                {t.single && !triggers.some((g) => g.toUpperCase() === t.single!.toUpperCase()) && (
                  <option value={t.single}>{t.single}</option>
                )}
                {triggers.map((g) => (
                  <option key={g} value={g}>
                    {g}
                  </option>
                ))}
              </select>
              <label htmlFor={`task-priority-${ti}`}>Priority</label>
              <CommitInput
                id={`task-priority-${ti}`}
                className="rs-cell-input"
                inputMode="numeric"
                data-testid={`task-priority-${ti}`}
                value={String(t.priority)}
                onCommit={(text) => int(text) !== t.priority && editTask(ti, { priority: int(text) })}
              />
            </div>
            {(['name', 'cycleMs', 'single', 'priority'] as const).map((f) => {
              const m = problemOf(ti, f);
              return m ? (
                <p key={f} className="rs-field-problem" role="alert" data-testid={`task-problem-${ti}`}>
                  {m}
                </p>
              ) : null;
            })}
            <table className="rs-task-programs">
              <thead>
                <tr>
                  <th scope="col">Program instance</th>
                  <th scope="col">Program</th>
                  <th scope="col">
                    <span className="rs-visually-hidden">Order</span>
                  </th>
                </tr>
              </thead>
              <tbody>
                {t.programs.map((p, pi) => (
                  <tr key={pi} data-testid={`task-${ti}-program-${pi}`}>
                    <td>
                      <CommitInput
                        className="rs-cell-input rs-mono"
                        aria-label={`Instance name of ${p.pou}`}
                        value={p.instance}
                        onCommit={(text) => editProgram(ti, pi, { instance: text.trim() })}
                      />
                      {problemOf(ti, 'instance', pi) && (
                        <p className="rs-field-problem" role="alert">
                          {problemOf(ti, 'instance', pi)}
                        </p>
                      )}
                    </td>
                    <td>
                      <select
                        className="rs-cell-input"
                        aria-label={`Program run by ${p.instance}`}
                        value={p.pou}
                        onChange={(e) => editProgram(ti, pi, { pou: e.target.value })}
                      >
                        {!programs.some((x) => x.name === p.pou) && <option value={p.pou}>{p.pou}</option>}
                        {programs.map((x) => (
                          <option key={x.id} value={x.name}>
                            {x.name}
                          </option>
                        ))}
                      </select>
                      {problemOf(ti, 'pou', pi) && (
                        <p className="rs-field-problem" role="alert">
                          {problemOf(ti, 'pou', pi)}
                        </p>
                      )}
                    </td>
                    <td className="rs-task-order">
                      <button
                        type="button"
                        className="rs-icon-button"
                        data-order={-1}
                        disabled={pi === 0}
                        title="Run earlier"
                        onClick={() => moveProgram(ti, pi, -1)}
                      >
                        ↑
                      </button>
                      <button
                        type="button"
                        className="rs-icon-button"
                        data-order={1}
                        disabled={pi === t.programs.length - 1}
                        title="Run later"
                        onClick={() => moveProgram(ti, pi, 1)}
                      >
                        ↓
                      </button>
                      <button
                        type="button"
                        className="rs-icon-button"
                        title={`Stop running ${p.instance}`}
                        data-testid={`task-${ti}-remove-${pi}`}
                        onClick={() => {
                          // The keyboard goes to the next instance's ✕ (the previous one's at the end, else the add list).
                          const next = pi < t.programs.length - 1 ? pi : pi - 1;
                          focusNext.current =
                            next >= 0
                              ? `[data-testid="task-${ti}-remove-${next}"]`
                              : `[data-testid="task-add-program-${ti}"]`;
                          editTask(ti, { programs: t.programs.filter((_, i) => i !== pi) });
                        }}
                      >
                        ✕
                      </button>
                    </td>
                  </tr>
                ))}
              </tbody>
            </table>
            <div className="rs-task-actions">
              <select
                className="rs-cell-input"
                aria-label={`Add a program instance to ${t.name}`}
                data-testid={`task-add-program-${ti}`}
                value=""
                disabled={draft !== undefined}
                onChange={(e) =>
                  e.target.value && say(store.getState().addProgramInstance(ti, e.target.value))
                }
              >
                <option value="">Run a program…</option>
                {programs.map((x) => (
                  <option key={x.id} value={x.name}>
                    {x.name}
                  </option>
                ))}
              </select>
              <button
                type="button"
                className="rs-button"
                data-testid={`task-delete-${ti}`}
                disabled={draft !== undefined}
                onClick={() => {
                  focusNext.current = '[data-testid="task-add"]';
                  say(store.getState().deleteTask(ti));
                }}
              >
                Delete task
              </button>
            </div>
          </fieldset>
        ))}
        <button
          type="button"
          className="rs-button"
          data-testid="task-add"
          disabled={draft !== undefined}
          onClick={() => say(store.getState().addTask())}
        >
          Add task
        </button>
      </div>
      {message && (
        <p className="rs-field-problem" role="alert" data-testid="tasks-message">
          {message}
        </p>
      )}
    </ModalDialog>
  );
}

/** What runs when, in words: "Tick 10 ms: Fast runs every tick (10 ms); E runs when StartPulse rises." */
function scheduleText(tasks: readonly Task[]): string {
  const s = taskSchedule(tasks);
  if (s.tasks.length === 0) return 'No task runs a program yet.';
  if (s.tickMs === 0)
    return `No task has an interval: MATIEC needs a periodic task to set the tick, so Run refuses this (LD-E20). ${describeSchedule(s)}.`;
  const cycle = s.multiRate
    ? " The simulator's Cycle is this tick."
    : " The simulator's Cycle starts at this interval and can be changed there.";
  return `Tick ${s.tickMs} ms: ${describeSchedule(s)}.${cycle}`;
}

/**
 * A field that commits on Enter (keeping the keyboard) or when it loses focus, and shows what the
 * project holds whenever that changes (an undo, a refused draft, a trimmed name).
 */
function CommitInput({
  value,
  onCommit,
  onKeyDown,
  ...rest
}: {
  readonly value: string;
  readonly onCommit: (text: string) => void;
} & Omit<InputHTMLAttributes<HTMLInputElement>, 'value' | 'defaultValue' | 'onChange' | 'onBlur'>) {
  const [text, setText] = useState(value);
  const [shown, setShown] = useState(value);
  if (shown !== value) {
    setShown(value);
    setText(value);
  }
  return (
    <input
      {...rest}
      value={text}
      onChange={(e) => setText(e.target.value)}
      onBlur={() => text !== value && onCommit(text)}
      onKeyDown={(e) => {
        if (e.key === 'Enter' && text !== value) onCommit(text);
        onKeyDown?.(e);
      }}
    />
  );
}
