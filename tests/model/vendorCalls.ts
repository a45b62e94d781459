// Which vendor library blocks a PLCopen file calls, and the check that each is known with every
// pin the file wires (tests/model/vendorBlocks.test.ts on a fixture, tests/interop on the corpus).
import { expect } from 'vitest';
import { blockSignature } from '../../src/model/blocks';
import { newProject } from '../../src/model/factory';
import { blockLibrary } from '../../src/model/library';
import type { ExternalBlockPin } from '../../src/model/project';
import { childrenNamed, descend, parseXml, type XmlElement } from '../../src/plcopen/xml/parse';

interface Call {
  readonly typeName: string;
  /** A function block call names its instance. */
  readonly instance?: string;
  readonly pins: readonly ExternalBlockPin[];
}

/** Every `<block>` of a PLCopen file and the pins it wires (EN/ENO left out), with the POUs it defines. */
export function blockCalls(text: string): { calls: Call[]; pous: Set<string> } {
  const doc = parseXml(text);
  const calls: Call[] = [];
  const pous = new Set<string>();
  const dirs = [
    ['inputVariables', 'in'],
    ['outputVariables', 'out'],
    ['inOutVariables', 'inOut'],
  ] as const;
  const walk = (el: XmlElement) => {
    if (el.name === 'pou') pous.add(el.attrs['name']!.toUpperCase());
    if (el.name === 'block') {
      const pins = dirs.flatMap(([list, dir]) =>
        childrenNamed(descend(el, list) ?? el, 'variable')
          .map((v) => ({ name: v.attrs['formalParameter']!, dir }))
          .filter((p) => !['EN', 'ENO'].includes(p.name.toUpperCase())),
      );
      calls.push({ typeName: el.attrs['typeName']!, instance: el.attrs['instanceName'], pins });
    }
    el.children.forEach(walk);
  };
  walk(doc);
  return { calls, pous };
}

/** The calls of blocks that are neither standard nor defined in the file (its text). */
export const foreignCalls = (text: string) => {
  const { calls, pous } = blockCalls(text);
  return calls.filter((c) => !blockSignature(c.typeName) && !pous.has(c.typeName.toUpperCase()));
};

/** Every call a file makes to a block of a shipped vendor library is known, with every pin it wires. */
export function expectVendorCallsKnown(text: string, expected: readonly string[]): void {
  const calls = foreignCalls(text);
  expect([...new Set(calls.map((c) => c.typeName))].sort()).toEqual(expected);
  const lib = blockLibrary(newProject('P'));
  for (const call of calls) {
    expect(lib.isExternal(call.typeName), call.typeName).toBe(true);
    const sig = lib.signature(call.typeName)!;
    expect(sig.category).toBe('external');
    expect(sig.kind).toBe('fb');
    for (const pin of call.pins) {
      const side = pin.dir === 'in' ? sig.inputs : sig.outputs;
      expect(pinNames(side), `${call.typeName}.${pin.name}`).toContain(pin.name);
    }
  }
}

export const pinNames = (pins: readonly { name: string }[]) => pins.map((p) => p.name);

