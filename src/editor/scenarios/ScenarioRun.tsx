// A scenario run in a simulation of its own (its own worker and session), never the live one: the
// live PLC keeps its scan, state and forces while a scenario runs. A failure shows its first
// divergent scan with "Why?" from that run, scan by scan (issue 22, 2.2).
import { useState } from 'react';
import { useStore } from 'zustand';
import type { Project, Scenario } from '../../model/project';
import type { ScenarioResult } from '../../sim/scenario';
import { createWorkerTransport } from '../../sim/host';
import type { SimState, SimStore } from '../../store/simState';
import { createSimStore } from '../../store/simStore';
import { errorText } from './scenarioText';

let scenarioSim: SimStore | undefined;
/** The simulation scenario runs use: separate from the app's (never bound to the gateway). */
export function getScenarioSimStore(): SimStore {
  return (scenarioSim ??= createSimStore(createWorkerTransport()));
}

/** Runs the scenario from a cold start in the scenario simulation; a failure is explained at its first divergent scan. */
export async function runScenarioApart(project: Project, scenario: Scenario): Promise<ScenarioResult> {
  const sim = getScenarioSimStore();
  // The simulator could not run it at all (it failed or stopped): a failed result saying why, not a run that never ends.
  const result = await sim
    .getState()
    .replayScenario(project, scenario)
    .catch((error: Error): ScenarioResult => ({ name: scenario.name, ok: false, scans: 0, divergences: [], error: error.message }));
  // Why? at the first divergence, or at the machine's consequence the run failed on (the tank
  // overflowed: the machine as the scan left it, which the program drove).
  const d = result.divergences[0];
  const target = d?.name ?? result.consequence;
  if (target) sim.getState().explain({ kind: 'variable', name: target }, d?.scan ?? result.scans);
  return result;
}

const selectExplanation = (s: SimState) => s.explanation;
const selectHistory = (s: SimState) => s.history;

export function ScenarioRunView({ name, result, onClose }: { name: string; result: ScenarioResult; onClose: () => void }) {
  const sim = getScenarioSimStore();
  const explanation = useStore(sim, selectExplanation);
  const history = useStore(sim, selectHistory);
  const first = result.divergences[0];
  const [target] = useState(first?.name ?? result.consequence);
  const at = explanation?.scan ?? first?.scan ?? (result.consequence ? result.scans : undefined);
  const go = (scan: number) => {
    if (!target || !history) return;
    const s = Math.max(history.first, Math.min(history.last, scan));
    sim.getState().explain({ kind: 'variable', name: target }, s);
  };
  return (
    <section className="rs-scenario-run" aria-label="Scenario run" data-testid="scenario-run">
      <div className="rs-sim-panel-bar">
        <strong>{name}</strong>
        <span data-testid="scenario-run-result">
          {result.error
            ? errorText(result)
            : result.ok
              ? `PASS in ${result.scans} scan${result.scans === 1 ? '' : 's'}`
              : `FAIL at scan ${first?.scan}: ${result.divergences.map((d) => `${d.name} expected ${d.expected}, got ${d.actual}`).join('; ')}`}
        </span>
        <button type="button" className="rs-sim-btn" onClick={onClose}>Close</button>
      </div>
      <p className="rs-sim-empty" data-testid="scenario-run-note">
        Ran from a cold start in a simulation of its own: the live session (its scan, values and forces) is untouched.
      </p>
      {target && explanation && (
        <div data-testid="scenario-why">
          <div className="rs-sim-panel-bar">
            <button type="button" className="rs-sim-btn" aria-label="Previous scan" disabled={!history || at === undefined || at <= history.first} onClick={() => at !== undefined && go(at - 1)}>◀</button>
            <span className="rs-why-title" data-testid="scenario-why-title">{explanation.title}</span>
            <button type="button" className="rs-sim-btn" aria-label="Next scan" disabled={!history || at === undefined || at >= history.last} onClick={() => at !== undefined && go(at + 1)}>▶</button>
          </div>
          <ul className="rs-why-lines">
            {explanation.lines.map((l, i) => (
              <li key={i} className={l.startsWith('  ') ? 'rs-why-sub' : undefined}>{l.trim()}</li>
            ))}
          </ul>
        </div>
      )}
    </section>
  );
}
