// Tests (issue 14): the project's test scenarios. Run them all (pass/fail per scenario); a failure
// opens in the timeline at its first divergent scan with "Why?" on the differing output. Record a
// scenario from the simulation (the inputs toggled and the outputs seen), edit it as a table or CSV.
import { useEffect, useMemo, useRef, useState, type RefObject } from 'react';
import type { Project, Scenario } from '../../model/project';
import { parseScenario, runScenario, type ScenarioResult } from '../../sim/scenario';
import { useDocument, useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import { useSimStore } from '../sim/simContext';
import '../history/history.css';

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
  const runAll = () => {
    const out: Record<string, ScenarioResult> = {};
    for (const sc of scenarios) out[sc.name] = runScenario(project, sc).result;
    setResults(out);
  };
  const open = async (sc: Scenario) => {
    const r = await sim.getState().replayScenario(project, sc);
    setResults((prev) => ({ ...prev, [sc.name]: r }));
    const d = r.divergences[0];
    if (d) {
      sim.getState().seekHistory(d.scan);
      sim.getState().explain({ kind: 'variable', name: d.name }, d.scan);
    }
  };
  const record = async () => {
    const layout = sim.getState().layout;
    if (!layout || !sim.getState().history) {
      setMessage('Run the program and toggle its inputs first: the scenario is recorded from the scan history.');
      return;
    }
    const inputs = layout.variables.filter((v) => v.role === 'input').map((v) => v.name);
    const outputs = layout.variables.filter((v) => v.role === 'output').map((v) => v.name);
    const csv = await sim.getState().exportHistory({ format: 'scenario', inputs, outputs });
    let n = scenarios.length + 1;
    while (scenarios.some((s) => s.name === `Recorded ${n}`)) n++;
    save([...scenarios, { name: `Recorded ${n}`, csv }]);
    setMessage(`Recorded ${n} added from the scan history (${inputs.length} inputs, ${outputs.length} outputs expected).`);
  };
  const passed = Object.values(results).filter((r) => r.ok).length;
  const failed = Object.values(results).filter((r) => !r.ok).length;
  return (
    <div className="rs-sim-panel" data-testid="tests-panel">
      <div className="rs-sim-panel-bar">
        <button type="button" className="rs-sim-btn" disabled={scenarios.length === 0} onClick={runAll} data-testid="tests-run-all">Run all</button>
        <button type="button" className="rs-sim-btn" onClick={() => void record()} data-testid="tests-record"
          title="A scenario from the recorded scans: the inputs where they changed and the outputs seen">
          Record from simulation
        </button>
        {Object.keys(results).length > 0 && (
          <span data-testid="tests-summary">
            {passed} passed, {failed} failed
          </span>
        )}
        {message && <span role="status">{message}</span>}
      </div>
      {scenarios.length === 0 ? (
        <p className="rs-sim-empty">No test scenarios. Run the program, toggle inputs, then Record from simulation.</p>
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
                      title="Run it in the simulator; a failure opens at its first divergent scan with Why?">
                      {r && !r.ok ? 'Open failure in timeline' : 'Run in simulator'}
                    </button>
                    <button type="button" className="rs-sim-btn" onClick={() => setEditing(editing === i ? undefined : i)}>Edit</button>
                    <button type="button" className="rs-sim-btn" onClick={() => save(scenarios.filter((_, k) => k !== i))}>Delete</button>
                  </td>
                </tr>
              );
            })}
          </tbody>
        </table>
      )}
      {editing !== undefined && scenarios[editing] && (
        <ScenarioEditor key={editing} scenario={scenarios[editing]} onSave={(next) => save(scenarios.map((s, k) => (k === editing ? next : s)))} />
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
    const cells = lines[line]!.split(',');
    while (cells.length <= col + 1) cells.push('');
    cells[col + 1] = text;
    lines[line] = cells.join(',');
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
              <tr key={ri}>
                <td>{r.scan}</td>
                {parsed.s.columns.map((_, ci) => (
                  <td key={ci}>
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
