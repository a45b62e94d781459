// Connector names in PLCopen are the body's (Beremiz's generator looks a continuation's connector up
// in the whole body); in the editor and the engine a connector pair joins within its network. A
// name that an earlier network of the POU already uses is renamed in the later network (connector
// and continuations alike) to C<n>, unused anywhere in the POU: on import, so the layout's C1, C2, …
// of each network stay apart, and on export, for pairs a user drew with one name in two networks.
import type { Network } from '../model/project';

const pairName = (el: Network['elements'][number]): string | undefined =>
  el.kind === 'connector' || el.kind === 'continuation' ? el.name : undefined;

/** The networks with every connector name used by one network only (the same array when it already is). */
export function uniqueConnectorNames(networks: readonly Network[]): readonly Network[] {
  const all = new Set<string>();
  for (const net of networks) for (const el of net.elements) all.add(pairName(el)?.toUpperCase() ?? '');
  const used = new Set<string>();
  let counter = 0;
  let changed = false;
  const out = networks.map((net) => {
    const rename = new Map<string, string>();
    for (const el of net.elements) {
      const key = pairName(el)?.toUpperCase();
      if (key === undefined || rename.has(key)) continue;
      if (!used.has(key)) rename.set(key, '');
      else {
        let name: string;
        do name = `C${++counter}`;
        while (all.has(name) || used.has(name));
        rename.set(key, name);
      }
    }
    for (const [key, to] of rename) used.add(to || key);
    if (![...rename.values()].some(Boolean)) return net;
    changed = true;
    return {
      ...net,
      elements: net.elements.map((el) => {
        const to = rename.get(pairName(el)?.toUpperCase() ?? '');
        return to && (el.kind === 'connector' || el.kind === 'continuation') ? { ...el, name: to } : el;
      }),
    };
  });
  return changed ? out : networks;
}
