// A box imported with a PLCopen executionOrderId keeps it through edits, but a pasted or duplicated
// copy drops it: under the openplc profile an ordered box runs before every coil of its POU, and a
// copy must not jump that queue (LD-SEMANTICS.md section 6).
import { describe, expect, test } from 'vitest';
import type { BoxElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';

function store() {
  const box: BoxElement = {
    id: 'b1' as ElementId,
    kind: 'box',
    row: 0,
    col: 1,
    blockType: 'R_TRIG',
    instance: 'R1',
    inputs: {},
    outputs: { Q: 'M' },
    executionOrder: 3,
    outputOrders: { Q: 4 },
  };
  const pou = newPou('Main', {
    variables: [variable('R1', 'R_TRIG'), variable('M', 'BOOL')],
    networks: [newNetwork({ rows: 2, cols: 4, elements: [box] })],
  });
  const s = createDocumentStore(newProject('p', { pous: [pou] }));
  const boxes = () => selectNetworks(s.getState()).map((n) => n.elements.filter((e): e is BoxElement => e.kind === 'box'));
  return { s, boxes };
}

describe('executionOrder on copies', () => {
  test('duplicating the box: the copy has no execution order, the original keeps its own', () => {
    const { s, boxes } = store();
    const net = selectNetworks(s.getState())[0]!.id;
    const [copy] = s.getState().duplicateElements(net, ['b1' as ElementId]);
    const [first] = boxes();
    expect(first!.find((b) => b.id === 'b1')).toMatchObject({ executionOrder: 3, outputOrders: { Q: 4 } });
    const dup = first!.find((b) => b.id === copy)!;
    expect(dup.blockType).toBe('R_TRIG');
    expect(dup.executionOrder).toBeUndefined();
    expect(dup.outputOrders).toBeUndefined();
  });

  test('duplicating the network: the new network\'s box has no execution order', () => {
    const { s, boxes } = store();
    const net = selectNetworks(s.getState())[0]!.id;
    s.getState().duplicateNetworks([net], 'new');
    const [first, second] = boxes();
    expect(first![0]!.executionOrder).toBe(3);
    expect(second).toHaveLength(1);
    expect(second![0]!.executionOrder).toBeUndefined();
    expect(second![0]!.outputOrders).toBeUndefined();
  });
});
