// The checker worker gets the first version of the project as JSON and each later one as a
// difference from the version before (src/editor/problems/check.worker.ts): its findings must be
// those of a check of the whole version, and a difference on a version it does not hold is refused.
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import type { Diagnostic } from '../../src/engine/api';
import type { CheckRequest } from '../../src/editor/problems/check.worker';
import { runChecks } from '../../src/editor/problems/checkRun';
import { diffProject } from '../../src/sim/projectDelta';
import type { Project } from '../../src/model/project';
import { bottleFillerProject } from '../../bench/bottleFiller';

const answers: { seq: number; diagnostics: Diagnostic[] }[] = [];
const scope: { postMessage(m: { seq: number; diagnostics: Diagnostic[] }): void; onmessage?: (e: { data: CheckRequest }) => void } = {
  postMessage: (m) => answers.push(m),
};
const saved = (globalThis as { self?: unknown }).self;

beforeAll(async () => {
  (globalThis as { self?: unknown }).self = scope;
  await import('../../src/editor/problems/check.worker');
});
afterAll(() => {
  (globalThis as { self?: unknown }).self = saved;
});

const send = (request: CheckRequest) => {
  scope.onmessage!({ data: request });
  return answers[answers.length - 1]!;
};

/** Main's first contact reads `name` instead. */
function retyped(p: Project, name: string): Project {
  const main = p.pous[0]!;
  const k = main.networks.findIndex((n) => n.elements.some((e) => e.kind === 'contact'));
  const net = main.networks[k]!;
  const i = net.elements.findIndex((e) => e.kind === 'contact');
  const networks = main.networks.map((n, j) => (j === k ? { ...net, elements: net.elements.map((e, m) => (m === i ? { ...e, variable: name } : e)) } : n));
  return { ...p, pous: [{ ...main, networks }, ...p.pous.slice(1)] };
}

describe('the checker worker checks each version sent as a difference as a whole check would', () => {
  test('the first version as JSON, then an undeclared name, then the name fixed: the findings of each whole version', () => {
    const v1 = bottleFillerProject(2);
    expect(send({ seq: 1, projectText: JSON.stringify(v1) }).diagnostics).toEqual(runChecks(structuredClone(v1)));
    const v2 = retyped(v1, 'NoSuchSensor');
    const wrong = send({ seq: 2, delta: diffProject(v1, 1, v2) });
    expect(wrong.seq).toBe(2);
    expect(wrong.diagnostics).toEqual(runChecks(structuredClone(v2)));
    expect(wrong.diagnostics.some((d) => d.severity === 'error' && d.message.includes('NoSuchSensor'))).toBe(true);
    const v3 = retyped(v2, 'BottleAtFill');
    const fixed = send({ seq: 3, delta: diffProject(v2, 2, v3) });
    expect(fixed.diagnostics).toEqual(runChecks(structuredClone(v3)));
    expect(fixed.diagnostics.some((d) => d.message.includes('NoSuchSensor'))).toBe(false);
  });

  test('a difference from a version the worker does not hold is refused, never checked against the wrong base', () => {
    const v1 = bottleFillerProject(2);
    send({ seq: 10, projectText: JSON.stringify(v1) });
    const count = answers.length;
    expect(() => send({ seq: 12, delta: diffProject(v1, 11, retyped(v1, 'Other')) })).toThrow(/not the version 11/);
    expect(answers.length).toBe(count);
  });
});
