// Debugger marks in a network's header: the breakpoint toggle, "next" when execution is paused
// before this network (with a frame around the whole network), "skipped" when a jump skipped it,
// "not run" when no network of the body ran (its task was not due in this tick, or it was not called);
// with online changes applied on request, "changed · not applied" on a network the running program does not have.
import type { Network } from '../../model/project';
import { gridHeight, headerHeight } from '../canvas/geometry';
import { useSim, useSimStore } from './simContext';
import { useBodyRan, useHasBreakpoint, useIsCurrentNetwork, useNetworkExecuted } from './useSimOverlay';

export function NetworkSimMarker({
  network,
  index,
  pitch,
  rows,
}: {
  network: Network;
  index: number;
  pitch?: number;
  rows?: number;
}) {
  const sim = useSimStore();
  const breakpoint = useHasBreakpoint(network.id);
  const current = useIsCurrentNetwork(network.id);
  const executed = useNetworkExecuted(network.id);
  const bodyRan = useBodyRan();
  const unapplied = useSim((s) => s.unapplied?.networks.has(network.id) === true);
  const no = index + 1;
  return (
    <>
      <button
        type="button"
        className={`rs-sim-bp${breakpoint ? ' rs-sim-bp-on' : ''}`}
        aria-pressed={breakpoint}
        aria-label={`Toggle breakpoint on network ${no}`}
        title={breakpoint ? 'Breakpoint: execution pauses before this network (click to remove)' : 'Set a breakpoint: execution pauses before this network'}
        onClick={() => sim.getState().toggleBreakpoint(network.id)}
        data-testid={`network-breakpoint-${index}`}
      >
        ●
      </button>
      {unapplied && (
        <span className="rs-sim-changed-badge" data-testid={`network-unapplied-${index}`}
          title="Changed since the running program was loaded: not applied yet (Apply in the simulation toolbar)">
          changed · not applied
        </span>
      )}
      {current && (
        <>
          <span className="rs-sim-next-badge" data-testid={`network-next-${index}`}>▶ runs next</span>
          <div className="rs-sim-current-frame" style={{ height: headerHeight(network) + gridHeight(network, pitch, rows ?? network.rows) - 4 }} aria-hidden />
        </>
      )}
      {executed === false && (
        <span
          className="rs-sim-skipped"
          title={
            bodyRan === false
              ? 'This body did not run in this scan: its task was not due in this tick, or nothing called it'
              : 'A jump or return skipped this network in this scan'
          }
        >
          {bodyRan === false ? 'not run' : 'skipped'}
        </span>
      )}
    </>
  );
}
