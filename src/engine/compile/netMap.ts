// A network while it is lowered: the map from graph nets to power-flow locals and data sources
// (NetMap), the pending network of the openplc order (PendingNetwork), and the IR assembled from
// them (networkIR). Shared by lower.ts, generated.ts, box.ts, boxPins.ts, userCall.ts and
// aggregatePins.ts.
import type { Network } from '../../model/project';
import type { PouContext } from './context';
import { upstream, type NetworkGraph } from './graph';
import type { NetworkIR, Source } from './ir';
import type { Store } from './symbols';

/** Maps graph nets to what the generated code reads for them. */
export class NetMap {
  private readonly power = new Map<number, number>();
  private count = 0;
  /** Graph net -> value source when the net carries a non-BOOL value from a box output. */
  readonly data = new Map<number, Source>();
  /** Nets driven by a block output that is not BOOL by signature, before that block is lowered. */
  readonly dataPending = new Set<number>();
  /**
   * openplc profile: data slots a block with an executionOrderId read before the function driving
   * the net ran (its stored output, generated.ts); that function writes its output there.
   */
  readonly heldData = new Map<number, { readonly store: Store; readonly slot: number }>();
  constructor(readonly g: NetworkGraph) {
    for (const node of g.nodes) {
      if (node.el.kind !== 'box') continue;
      for (const t of node.outputs)
        if (node.layout?.outputs.find((p) => p.name === t.pin)?.type !== 'BOOL') this.dataPending.add(t.net);
    }
  }

  /**
   * openplc profile (generated.ts): the locals of the reading being generated, which take
   * precedence; every reading of a contact gets locals of its own.
   */
  overlay: ReadonlyMap<number, number> | undefined;

  /** A new power-flow local, bound to no graph net (openplc readings). */
  fresh(): number {
    return this.count++;
  }

  /** The power-flow local for a graph net (allocated on first use). */
  powerNet(net: number): number {
    const over = this.overlay?.get(net);
    if (over !== undefined) return over;
    let id = this.power.get(net);
    if (id === undefined) {
      id = this.count++;
      this.power.set(net, id);
    }
    return id;
  }
  /** Makes a graph net share an existing power-flow local (a coil's right side with its left side). */
  alias(net: number, id: number): void {
    if (!this.power.has(net)) this.power.set(net, id);
  }
  hasPower(net: number): boolean {
    return this.power.has(net);
  }
  get powerCount(): number {
    return this.count;
  }
  railNets(): number[] {
    return [
      ...new Set(
        [...this.power].filter(([net]) => net >= 0 && this.g.nets[net]!.leftRail).map(([, id]) => id),
      ),
    ];
  }
  /** True when the net is driven: by the left rail or an element's output (LD-R03: a line that starts nowhere is not). */
  isFed(net: number): boolean {
    return upstream(this.g, net).fed;
  }
  /** True when something besides the terminal itself is attached to the net (a wire or another element). */
  isWired(net: number): boolean {
    const n = this.g.nets[net]!;
    return (
      n.leftRail ||
      n.links.length + n.vlinks.length + n.feeds.length + n.feedsOut.length > 0 ||
      n.sources.length + n.sinks.length > 1
    );
  }
}

/** A network being lowered: `finish` gives its IR once every network of the POU body is started. */
export interface PendingNetwork {
  finish(): NetworkIR | undefined;
}

/** A lowered network's IR from its operations and its elements' nets. */
export function networkIR(
  ctx: PouContext,
  network: Network,
  index: number,
  nets: NetMap,
  parts: Pick<NetworkIR, 'ops' | 'elementNets' | 'vlinkNets' | 'late' | 'early' | 'earlyOrder' | 'earlyTurns'>,
): NetworkIR {
  return {
    index: ctx.first + index,
    ...(network.label ? { label: network.label } : {}),
    ops: parts.ops,
    netCount: nets.powerCount,
    railNets: nets.railNets(),
    elementNets: parts.elementNets,
    vlinkNets: parts.vlinkNets,
    constants: [],
    ...(parts.late?.length ? { late: parts.late } : {}),
    ...(parts.early?.length ? { early: parts.early, earlyOrder: parts.earlyOrder ?? [] } : {}),
    ...(parts.earlyTurns?.length ? { earlyTurns: parts.earlyTurns } : {}),
  };
}
