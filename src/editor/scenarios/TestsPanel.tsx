// Tests (issue 14): the project's test scenarios. Run them all (pass/fail per scenario); run one in a
// simulation of its own (never the live one), a failure shown at its first divergent scan with "Why?"
// on the differing output. Record a scenario from the scans since the last cold start (the inputs
// toggled and the outputs seen), start a new one, edit it as a table or CSV.
import { useEffect, useMemo, useRef, useState, type RefObject } from 'react';
import type { Project, Scenario } from '../../model/project';
import { parseScenario, type ScenarioResult } from '../../sim/scenario';
import { useDocument, useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import { useSimStore } from '../sim/simContext';
import { runScenariosOffPage } from './scenarioRunner';
import '../history/history.css';
import { readCsv, csvRow } from '../../sim/csv';
import { newScenarioCsv, newScenarioName } from '../../sim/scenarioTemplate';
import { runScenarioApart, ScenarioRunView } from './ScenarioRun';

const selectProject = (s: { project: Project }) => s.project;

export function TestsPanel() {
  const doc = useDocumentStore();
  const sim = useSimStore();
  const project = useDocument(selectProject);
  const scenarios = project.scenarios ?? [];
  const [results, setResults] = useState<Record<string, ScenarioResult>>({});
  const [editing, setEditing] = useState<number | undefined>();
  const [message, setMessage] = useState<string | undefined>();
  const save = (next: Scenario[]) => doc.getState().updateProject({ scenarios: next });
  const [running, setRunning] = useState(false);
  const runAll = async () => {
    setRunning(true);
    try {
      const list = await runScenariosOffPage(project, scenarios);
      setResults(Object.fromEntries(list.map((r) => [r.name, r])));
    } finally {
      setRunning(false);
    }
  };
  // A run in a simulation of its own: the live session is never reset or touched.
  const [shown, setShown] = useState<{ name: string; result: ScenarioResult } | undefined>();
  const open = async (sc: Scenario) => {
    const r = await runScenarioApart(project, sc);
    setResults((prev) => ({ ...prev, [sc.name]: r }));
    setShown({ name: sc.name, result: r });
  };
  const record = async () => {
    const layout = sim.getState().layout;
    if (!layout || !sim.getState().history) {
      setMessage('Run the program and toggle its inputs first: the scenario is recorded from the scan history.');
      return;
    }
    const inputs = layout.variables.filter((v) => v.role === 'input').map((v) => v.name);
    const outputs = layout.variables.filter((v) => v.role === 'output').map((v) => v.name);
    let csv: string;
    try {
      csv = await sim.getState().exportHistory({ format: 'scenario', inputs, outputs });
    } catch (e) {
      // Recorded scans a scenario cannot replay (an online change, a force, not from a cold start).
      setMessage((e as Error).message);
      return;
    }
    let n = scenarios.length + 1;
    while (scenarios.some((s) => s.name === `Recorded ${n}`)) n++;
    save([...scenarios, { name: `Recorded ${n}`, csv }]);
    setMessage(`Recorded ${n} added from the scan history (${inputs.length} inputs, ${outputs.length} outputs expected).`);
  };
  // Results of the scenarios as they are (an edited or deleted scenario's old result is dropped).
  const current = scenarios.flatMap((sc) => (results[sc.name] ? [results[sc.name]!] : []));
  const passed = current.filter((r) => r.ok).length;
  const failed = current.filter((r) => !r.ok).length;
  const forget = (...names: string[]) =>
    setResults((prev) => Object.fromEntries(Object.entries(prev).filter(([n]) => !names.includes(n))));
  const addScenario = () => {
    const name = newScenarioName(scenarios);
    save([...scenarios, { name, csv: newScenarioCsv(project) }]);
    setEditing(scenarios.length);
    setMessage(`${name} added: one column per input and an expect column per output; fill in the scans and Save.`);
  };
  return (
    <div className="rs-sim-panel" data-testid="tests-panel">
      <div className="rs-sim-panel-bar">
        <button type="button" className="rs-sim-btn" disabled={scenarios.length === 0 || running} onClick={() => void runAll()} data-testid="tests-run-all">
          {running ? 'Running…' : 'Run all'}
        </button>
        <button type="button" className="rs-sim-btn" onClick={() => void record()} data-testid="tests-record"
          title="A scenario from the scans since the last cold start (Reset): the inputs where they changed and the outputs seen. A scenario always replays from a cold start.">
          Record from simulation
        </button>
        <button type="button" className="rs-sim-btn" onClick={addScenario} data-testid="tests-new"
          title="An empty scenario with the program's inputs and outputs as columns">
          New scenario
        </button>
        {current.length > 0 && (
          <span data-testid="tests-summary">
            {passed} passed, {failed} failed
          </span>
        )}
        {message && <span role="status">{message}</span>}
      </div>
      {scenarios.length === 0 ? (
        <p className="rs-sim-empty">No test scenarios. Press Reset, run the program and switch its inputs, then Record from simulation (a scenario replays from a cold start); or start one with New scenario.</p>
      ) : (
        <table className="rs-tests-table">
          <tbody>
            {scenarios.map((sc, i) => {
              const r = results[sc.name];
              return (
                <tr key={`${sc.name}-${i}`} data-testid="tests-row">
                  <td>{sc.name}</td>
                  <td>
                    {r === undefined ? '—' : r.ok ? <span className="rs-tests-pass">PASS</span> : <span className="rs-tests-fail">FAIL</span>}
                    {r && !r.ok && <div data-testid="tests-failure">{r.error ?? r.divergences.map((d) => `scan ${d.scan}: ${d.name} expected ${d.expected}, got ${d.actual}`).join('; ')}</div>}
                  </td>
                  <td>
                    <button type="button" className="rs-sim-btn" onClick={() => void open(sc)} data-testid="tests-open"
                      title="Runs it from a cold start in a simulation of its own (the live session is untouched); a failure shows its first divergent scan with Why?">
                      {r && !r.ok ? 'Why it failed' : 'Run'}
                    </button>
                    <button type="button" className="rs-sim-btn" onClick={() => setEditing(editing === i ? undefined : i)}>Edit</button>
                    <button type="button" className="rs-sim-btn" onClick={() => {
                      forget(sc.name);
                      // The editor stays on the scenario it shows (or closes with it).
                      if (editing !== undefined) setEditing(editing === i ? undefined : editing > i ? editing - 1 : editing);
                      save(scenarios.filter((_, k) => k !== i));
                    }}>Delete</button>
                  </td>
                </tr>
              );
            })}
          </tbody>
        </table>
      )}
      {shown && <ScenarioRunView key={`${shown.name}-${shown.result.scans}`} name={shown.name} result={shown.result} onClose={() => setShown(undefined)} />}
      {editing !== undefined && scenarios[editing] && (
        <ScenarioEditor key={`${editing}-${scenarios[editing].name}`} scenario={scenarios[editing]} onSave={(next) => {
          forget(scenarios[editing]!.name, next.name);
          save(scenarios.map((s, k) => (k === editing ? next : s)));
        }} />
      )}
    </div>
  );
}

/**
 * An open scenario editor needs room for its rows (a 160 px bottom panel shows one, at 1280×720):
 * the bottom panel grows to 45% of the window while it is open, back to its size after unless it
 * was resized meanwhile, and the editor is scrolled into view.
 */
function useRoomToEdit(ref: RefObject<HTMLDivElement | null>): void {
  const ui = useUiStore();
  useEffect(() => {
    const before = ui.getState().panels.bottom;
    const want = Math.round(window.innerHeight * 0.45);
    if (before < want) ui.getState().setPanels({ bottom: want, bottomCollapsed: false });
    const frame = requestAnimationFrame(() => ref.current?.scrollIntoView({ block: 'start' }));
    return () => {
      cancelAnimationFrame(frame);
      if (before < want && ui.getState().panels.bottom === want) ui.getState().setPanels({ bottom: before });
    };
  }, [ui, ref]);
}

/** The scenario as a table (cells editable) and as CSV. */
function ScenarioEditor({ scenario, onSave }: { scenario: Scenario; onSave: (s: Scenario) => void }) {
  const [name, setName] = useState(scenario.name);
  const [csv, setCsv] = useState(scenario.csv);
  const ref = useRef<HTMLDivElement>(null);
  useRoomToEdit(ref);
  const parsed = useMemo(() => {
    try {
      return { ok: true as const, s: parseScenario(csv, name) };
    } catch (e) {
      return { ok: false as const, message: (e as Error).message };
    }
  }, [csv, name]);
  const setCell = (row: number, col: number, text: string) => {
    if (!parsed.ok) return;
    const lines = csv.split('\n');
    const line = parsed.s.rows[row]!.line - 1;
    const cells = readCsv(lines[line]!.replace(/\r$/, '')).rows[0]?.cells ?? [];
    while (cells.length <= col + 1) cells.push('');
    if (cells[col + 1] === text) return;
    cells[col + 1] = text;
    lines[line] = csvRow(cells);
    setCsv(lines.join('\n'));
  };
  return (
    <div ref={ref} className="rs-scenario-editor" data-testid="scenario-editor">
      <label>
        Name <input type="text" value={name} onChange={(e) => setName(e.target.value)} />
      </label>
      {parsed.ok ? (
        <table className="rs-tests-table" data-testid="scenario-table">
          <thead>
            <tr>
              <th>scan</th>
              {parsed.s.columns.map((c, i) => (
                <th key={i}>{c.kind === 'expect' ? `expect ${c.name}${c.tolerance ? ` ±${c.tolerance}` : ''}` : c.name}</th>
              ))}
            </tr>
          </thead>
          <tbody>
            {parsed.s.rows.map((r, ri) => (
              <tr key={`${ri}-${r.scan}`}>
                <td>{r.scan}</td>
                {parsed.s.columns.map((_, ci) => (
                  // Keyed by the cell's text: when the CSV changes (edited or replaced), the field shows it.
                  <td key={`${ci}-${parsed.s.columns[ci]!.name}-${r.cells.get(ci) ?? ''}`}>
                    <input type="text" size={6} defaultValue={r.cells.get(ci) ?? ''} placeholder="*" aria-label={`scan ${r.scan} ${parsed.s.columns[ci]!.name}`}
                      onBlur={(e) => setCell(ri, ci, e.target.value)} />
                  </td>
                ))}
              </tr>
            ))}
          </tbody>
        </table>
      ) : (
        <p className="rs-timeline-message">{parsed.message}</p>
      )}
      <textarea className="rs-tests-csv" value={csv} onChange={(e) => setCsv(e.target.value)} aria-label="Scenario CSV" />
      <button type="button" className="rs-sim-btn" disabled={!parsed.ok || !name.trim()} onClick={() => onSave({ name: name.trim(), csv })}>Save scenario</button>
    </div>
  );
}
