// Side panel for debugging: breakpoints on networks (execution pauses before them), the network
// about to run, and every forced variable.
import { selectActivePou, useDocument } from '../../store/documentStore';
import type { SimState } from '../../store/simState';
import { formatLive } from './liveValues';
import { useSim, useSimStore } from './simContext';
import { useHasBreakpoint, useIsCurrentNetwork } from './useSimOverlay';
import './sim.css';

const selectForced = (s: SimState) => s.forced;
const selectLayout = (s: SimState) => s.layout;
const selectBreakpointCount = (s: SimState) => s.breakpoints.length;

export function SimulationPanel() {
  const pou = useDocument(selectActivePou);
  const sim = useSimStore();
  const count = useSim(selectBreakpointCount);
  return (
    <div className="rs-sim-panel" data-testid="simulation-panel">
      <h3 className="rs-sim-heading">
        Breakpoints{' '}
        <button type="button" className="rs-sim-btn" disabled={count === 0} onClick={() => sim.getState().clearBreakpoints()}>
          Clear all
        </button>
      </h3>
      <ol className="rs-sim-networks">
        {pou?.networks.map((n, i) => (
          <NetworkRow key={n.id} id={n.id} index={i} caption={[n.label, n.title].filter(Boolean).join(' · ')} />
        ))}
      </ol>
      <ForcedList />
    </div>
  );
}

function NetworkRow({ id, index, caption }: { id: string; index: number; caption: string }) {
  const sim = useSimStore();
  const on = useHasBreakpoint(id);
  const current = useIsCurrentNetwork(id);
  return (
    <li className={current ? 'rs-sim-current' : undefined} data-testid={`bp-network-${index + 1}`}>
      <label>
        <input type="checkbox" checked={on} onChange={() => sim.getState().toggleBreakpoint(id)}
          aria-label={`Breakpoint before network ${index + 1}`} />
        <span className="rs-sim-bp-dot" aria-hidden>{on ? '●' : '○'}</span> Network {index + 1}
        {caption && <span className="rs-sim-unit"> {caption}</span>}
        {current && <span className="rs-sim-next"> ◀ next</span>}
      </label>
    </li>
  );
}

function ForcedList() {
  const sim = useSimStore();
  const forced = useSim(selectForced);
  const layout = useSim(selectLayout);
  const typeOf = (name: string) => layout?.variables.find((v) => v.name.toUpperCase() === name)?.type ?? 'DINT';
  const nameOf = (key: string) => layout?.variables.find((v) => v.name.toUpperCase() === key)?.name ?? key;
  return (
    <>
      <h3 className="rs-sim-heading">
        Forced{' '}
        <button type="button" className="rs-sim-btn" disabled={forced.size === 0} onClick={() => sim.getState().unforceAll()}>
          Remove all forces
        </button>
      </h3>
      {forced.size === 0 ? (
        <p className="rs-sim-empty">Nothing is forced.</p>
      ) : (
        <ul className="rs-sim-forced-list">
          {[...forced].map(([key, value]) => (
            <li key={key}>
              <span className="rs-sim-forced">{nameOf(key)} = {formatLive(typeOf(key), value)}</span>{' '}
              <button type="button" className="rs-sim-btn" onClick={() => sim.getState().unforce(nameOf(key))}>Unforce</button>
            </li>
          ))}
        </ul>
      )}
    </>
  );
}
