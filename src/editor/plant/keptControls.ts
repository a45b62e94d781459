// The faults set on purpose and the operator switches turned ON, kept over a reload of the page
// (issue 26): a reload restarts the simulation as Reset does, and Reset keeps them, so a
// troubleshooting exercise's stuck switch or a key switch left ON is still there after it. Kept
// per tab (sessionStorage), for the machine attached when the page went; push buttons spring back
// and are not kept. Nothing of the program or the machine's state is: the machine starts over.
import type { PlantFrame } from '../../sim/sessionPlant';

export const KEPT_CONTROLS_KEY = 'rungsmith.plantControls';

export interface KeptControls {
  readonly id: string;
  readonly faults: readonly string[];
  /** Operator switches turned ON. */
  readonly switches: readonly string[];
}

/** What to keep of a frame (undefined: no machine attached). */
export function controlsOf(frame: PlantFrame | undefined): KeptControls | undefined {
  if (!frame) return undefined;
  const switches = frame.points
    .filter((p) => p.kind === 'operator' && p.control === 'switch' && frame.now.operator[p.name] === true)
    .map((p) => p.name);
  return { id: frame.id, faults: [...frame.now.faults], switches };
}

export function saveKeptControls(kept: KeptControls | undefined): void {
  try {
    if (!kept || (kept.faults.length === 0 && kept.switches.length === 0))
      sessionStorage.removeItem(KEPT_CONTROLS_KEY);
    else sessionStorage.setItem(KEPT_CONTROLS_KEY, JSON.stringify(kept));
  } catch {
    // Storage refused (private mode, full): they are just not kept over a reload.
  }
}

/** The controls kept by the page before this one in the tab, for the machine `id`; checked field by field. */
export function loadKeptControls(id: string): KeptControls | undefined {
  try {
    const raw: unknown = JSON.parse(sessionStorage.getItem(KEPT_CONTROLS_KEY) ?? 'null');
    if (!raw || typeof raw !== 'object') return undefined;
    const r = raw as Record<string, unknown>;
    const names = (v: unknown) =>
      Array.isArray(v) ? v.filter((x): x is string => typeof x === 'string') : [];
    if (r.id !== id) return undefined;
    return { id, faults: names(r.faults), switches: names(r.switches) };
  } catch {
    return undefined;
  }
}
