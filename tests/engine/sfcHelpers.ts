// Test helper: POUs written in SFC, as the PLCopen importer stores them (Pou.sfc).
import { newPou } from '../../src/model/factory';
import type { PouKind, SfcAssociation, SfcChart, SfcCode, Variable } from '../../src/model/project';

export const st = (text: string): SfcCode => ({ language: 'ST', text });

/** `step('Run', 'N Busy', 'D Lamp T#20ms')`; a name ending in `*` is the initial step. */
export function step(name: string, ...assocs: string[]): SfcChart['steps'][number] {
  const initial = name.endsWith('*');
  const associations: SfcAssociation[] = assocs.map((a) => {
    const [qualifier, action, duration] = a.split(/\s+/);
    return { qualifier: qualifier!, action: action!, ...(duration ? { duration } : {}) };
  });
  return { name: initial ? name.slice(0, -1) : name, initial, associations };
}

/** `tr('A', 'B', 'Go')`, `tr('A', 'B & C', 'Go', 2)`: from, to (several joined by &), ST condition, priority. */
export function tr(from: string, to: string, condition: string, priority?: number): SfcChart['transitions'][number] {
  return {
    from: from.split('&').map((s) => s.trim()),
    to: to.split('&').map((s) => s.trim()),
    condition: st(condition),
    ...(priority !== undefined ? { priority } : {}),
  };
}

export function sfcPou(name: string, kind: PouKind, variables: readonly Variable[], chart: SfcChart) {
  return { ...newPou(name, { kind, variables, networks: [] }), language: 'SFC' as const, sfc: chart };
}
