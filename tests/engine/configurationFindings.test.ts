// A configuration's programs are lowered once: their networks' findings come from the lowering of
// each program's first instance (compile/program.ts), not from a second lowering on the program's
// own symbol table. They must be exactly the findings of the program checked on its own (lowerPou),
// whatever the networks hold: errors, warnings, labels, program-wide rules, ST bodies.
import { describe, expect, test } from 'vitest';
import type { Diagnostic } from '../../src/engine/api';
import { lowerPou } from '../../src/engine/compile/pou';
import { compileProgram } from '../../src/engine/plc';
import type { LdElement } from '../../src/model/elements';
import type { Network, Pou, Project } from '../../src/model/project';
import { bottleFillerProject } from '../../bench/bottleFiller';
import { ladder } from './ladder';

const base = bottleFillerProject(2);

function withMain(p: Project, change: (main: Pou) => Pou): Project {
  return { ...p, pous: p.pous.map((x) => (x.name === 'Main' ? change(x) : x)) };
}
const addNetworks = (p: Project, nets: Network[]) => withMain(p, (m) => ({ ...m, networks: [...m.networks, ...nets] }));

/** What the program's own check reports for each program of the configuration, in order. */
function ownFindings(p: Project): Diagnostic[] {
  const out: Diagnostic[] = [];
  for (const name of ['Main', 'Signals']) lowerPou(p, p.pous.find((x) => x.name === name)!, p.profile, out, []);
  return out;
}

const cases: [string, Project][] = [
  ['the station as built', base],
  ['an undeclared variable in a contact (error)', addNetworks(base, [ladder(['[NoSuchInput] (Valve)'])])],
  ['the same coil written twice (program-wide rule)', addNetworks(base, [ladder(['[StartPB] (Valve)']), ladder(['[StopPB] (Valve)'])])],
  ['an empty network and a duplicate label', addNetworks(base, [{ ...ladder([]), label: 'Again' }, { ...ladder(['[StartPB] (Spare)']), label: 'Again' }])],
  [
    'a contact reading an INT (type error)',
    withMain(base, (m) => ({
      ...m,
      networks: m.networks.map((n, i) =>
        i === 0 ? { ...n, elements: n.elements.map((e) => (e.kind === 'contact' ? ({ ...e, variable: 'Count' } as LdElement) : e)) } : n,
      ),
    })),
  ],
];

describe("a configuration's programs: their networks' findings as when checked on their own", () => {
  for (const [what, p] of cases) {
    test(what, () => {
      const { diagnostics } = compileProgram(p, { configuration: true });
      const programs = diagnostics.filter((d) => d.pou === 'Main' || d.pou === 'Signals');
      expect(programs).toEqual(ownFindings(p));
    });
  }

  test('the cases do find something (errors and warnings in Main)', () => {
    const found = cases.slice(1).map(([, p]) => compileProgram(p, { configuration: true }).diagnostics.filter((d) => d.pou === 'Main'));
    for (const list of found) expect(list.length).toBeGreaterThan(0);
    expect(found.flat().some((d) => d.severity === 'error')).toBe(true);
    expect(found.flat().some((d) => d.severity === 'warning')).toBe(true);
  });
});
