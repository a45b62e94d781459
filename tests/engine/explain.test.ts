// "Why?" on hand-built networks: the explanation names what the engine really computed.
import { describe, expect, it } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { explain, liveScanView, type ExplainTarget } from '../../src/engine/explain';
import type { Project } from '../../src/model/project';
import { ladder, project, vars } from './ladder';

function setup(p: Project) {
  const { program, diagnostics } = compileProgram(p);
  if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
  const plc = createPlc(program, { cycleMs: 100 });
  const pou = p.pous[0]!;
  const why = (target: ExplainTarget, changedAt?: (name: string) => number | undefined) =>
    explain(program, pou, { ...liveScanView(plc, program), ...(changedAt ? { changedAt } : {}) }, target);
  const at = (network: number, variable: string, kind: 'coil' | 'contact') => ({
    kind: 'element' as const,
    network,
    element: pou.networks[network]!.elements.findIndex((e) => e.kind === kind && e.variable === variable),
  });
  return { plc, pou, why, at };
}

const motorProject = () =>
  project(vars('Start BOOL %IX0.0', 'Stop BOOL %IX0.1', 'Motor BOOL %QX0.0'), [
    ladder(['+ [Start] + [/Stop] (Motor)', '+ [Motor] +']),
  ]);

describe('Why? on a coil', () => {
  it('names the open Stop contact as what blocks every path to Motor', () => {
    const { plc, why, at, pou } = setup(motorProject());
    plc.write('Start', true);
    plc.write('Stop', true);
    plc.scan();
    const e = why(at(0, 'Motor', 'coil'));
    expect(e.title).toContain('Motor is FALSE');
    expect(e.lines.join('\n')).toMatch(/2 paths from the left rail could energise it/);
    expect(e.lines.join('\n')).toContain('|/| Stop is open: Stop is TRUE');
    const contact = (v: string) => pou.networks[0]!.elements.findIndex((x) => x.kind === 'contact' && x.variable === v);
    // Start's path is blocked by Stop; the seal-in path already at its first contact (Motor is FALSE).
    expect(e.marks.filter((m) => m.role === 'blocking').map((m) => m.element)).toEqual([contact('Stop'), contact('Motor')]);
    expect(e.paths).toHaveLength(2);
    expect(e.paths!.every((p) => p.blockedAt !== undefined)).toBe(true);
  });

  it('names the path that energised it, and the first open contact of each path when Start is released', () => {
    const { plc, why, at } = setup(motorProject());
    plc.write('Start', true);
    plc.scan();
    let e = why(at(0, 'Motor', 'coil'));
    expect(e.lines[0]).toBe('The coil ( ) Motor is energised through | | Start → |/| Stop.');
    expect(e.marks.filter((m) => m.role === 'path')).toHaveLength(2);
    plc.write('Start', false);
    plc.scan();
    e = why(at(0, 'Motor', 'coil'));
    // The seal-in path now carries power.
    expect(e.lines[0]).toBe('The coil ( ) Motor is energised through | | Motor → |/| Stop.');
    plc.write('Stop', true);
    plc.scan();
    e = why(at(0, 'Motor', 'coil'));
    const text = e.lines.join('\n');
    expect(text).toContain('| | Start → |/| Stop: | | Start is open: Start is FALSE');
    expect(text).toContain('| | Motor → |/| Stop: |/| Stop is open: Stop is TRUE');
  });

  it('says a network skipped by a jump did not run', () => {
    const p = project(vars('Skip BOOL', 'A BOOL', 'Y BOOL'), [ladder(['[Skip] >>END']), ladder(['[A] (Y)']), ladder(['[A] (A)'], { label: 'END' })]);
    const { plc, why, at } = setup(p);
    plc.write('Skip', true);
    plc.scan();
    const e = why(at(1, 'Y', 'coil'));
    expect(e.lines[0]).toBe('network 2 did not run in scan 1: a jump or RETURN skipped it, so nothing in it was evaluated.');
  });
});

describe('Why? on a variable', () => {
  it('names the last writer and lists the other coils on the same variable', () => {
    const p = project(vars('A BOOL', 'B BOOL', 'Y BOOL'), [ladder(['[A] (Y)']), ladder(['[B] (Y)'])]);
    const { plc, why } = setup(p);
    plc.write('A', true);
    plc.scan();
    const e = why({ kind: 'variable', name: 'Y' });
    const text = e.lines.join('\n');
    expect(e.title).toBe('Y is FALSE after scan 1');
    expect(text).toContain('Y was last written in scan 1 by ( ) Y in network 2, which wrote FALSE (after 1 other write in the same scan).');
    expect(text).toContain('Y has 2 writers');
    expect(e.marks.map((m) => [m.network, m.role])).toEqual([
      [1, 'writer'],
      [0, 'other-writer'],
      [1, 'blocking'],
    ]);
  });

  it('says an input comes from the input image and a latched output kept its value', () => {
    const p = project(vars('Start BOOL %IX0.0', 'Reset BOOL', 'Lamp BOOL'), [ladder(['[Start] (S:Lamp)']), ladder(['[Reset] (R:Lamp)'])]);
    const { plc, why } = setup(p);
    plc.write('Start', true);
    plc.scan();
    plc.write('Start', false);
    plc.scan();
    expect(why({ kind: 'variable', name: 'Start' }).lines[0]).toBe(
      'Nothing in the program writes Start: it is an input (%IX0.0), read from the input image at the start of the scan.',
    );
    expect(why({ kind: 'variable', name: 'Lamp' }).lines[0]).toBe('No writer of Lamp wrote it in scan 2: it kept its value from the scan before.');
  });

  it('gives the when-did-it-change link from the history callback', () => {
    const { plc, why } = setup(motorProject());
    plc.write('Start', true);
    plc.scan();
    const e = why({ kind: 'variable', name: 'Motor' }, (n) => (n.toUpperCase() === 'MOTOR' ? 1 : n.toUpperCase() === 'START' ? 1 : undefined));
    expect(e.links[0]).toEqual({ label: 'When did it change? Motor became TRUE at scan 1', scan: 1, target: { kind: 'variable', name: 'Motor' } });
    expect(e.links.some((l) => l.target.kind === 'variable' && l.target.name === 'Start')).toBe(true);
  });
});

describe('Why? on timers and counters', () => {
  it('explains a TON that is still timing with ET of PT and when IN went TRUE', () => {
    const p = project(vars('Go BOOL', 'T1 TON', 'Done BOOL'), [
      ladder(['[Go] # # (Done)', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#3s' } }] }),
    ]);
    const { plc, why, pou } = setup(p);
    plc.write('Go', true);
    plc.scans(13);
    const box = pou.networks[0]!.elements.findIndex((e) => e.kind === 'box');
    const e = why({ kind: 'element', network: 0, element: box }, (n) => (n.toUpperCase() === 'T1.IN' ? 1 : undefined));
    expect(e.title).toBe('T1 (TON) after scan 13');
    expect(e.lines[0]).toBe('T1.Q is FALSE: ET 1.2 s of PT 3 s: Q goes TRUE when IN has been TRUE for PT; IN is TRUE; IN went TRUE at scan 1.');
    const coil = why({ kind: 'variable', name: 'Done' });
    expect(coil.lines.join('\n')).toContain('TON T1: T1.Q is FALSE (ET 1.2 s of PT 3 s');
  });

  it('explains a counter output with CV of PV', () => {
    const p = project(vars('Pulse BOOL', 'C1 CTU', 'Full BOOL'), [
      ladder(['[Pulse] # # (Full)', '. # # .', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { PV: '3' } }] }),
    ]);
    const { plc, why } = setup(p);
    for (let i = 0; i < 2; i++) {
      plc.write('Pulse', true);
      plc.scan();
      plc.write('Pulse', false);
      plc.scan();
    }
    const e = why({ kind: 'variable', name: 'C1.Q' });
    expect(e.lines.join('\n')).toContain('C1.Q is FALSE: Q is CV >= PV: CV 2 of PV 3.');
  });
});
