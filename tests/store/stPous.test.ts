// ST POUs as first-class POUs (issue 25): created in ST from the store, their body text edited as
// named undo steps, called from LD networks with their pins (and calling LD FBs), run; a body that
// does not compile never runs (LD-E50), online or at Run.
import { describe, expect, test } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { createDocumentStore, selectLibrary, type DocumentStore } from '../../src/store/documentStore';
import { createSimStore } from '../../src/store/simStore';
import { loopback } from '../sim/loopback';

const pouByName = (p: Project, name: string) => p.pous.find((x) => x.name === name)!;

/**
 * A plant built as a user would: an LD FB Latch (Set/Reset -> Q), an ST FUNCTION Scale (Raw INT ->
 * REAL), an ST FB TankHysteresis calling Latch (the name Hysteresis is the standard block HYSTERESIS), and the LD program Main calling Scale and Hysteresis.
 */
function plant(): DocumentStore {
  const store = createDocumentStore(newProject('Plant'));
  const s = () => store.getState();
  const main = s().activePouId;

  const latch = s().addPou('FUNCTION_BLOCK', 'Latch')!;
  s().addVariable(variable('Set', 'BOOL', { varClass: 'input' }), latch);
  s().addVariable(variable('Reset', 'BOOL', { varClass: 'input' }), latch);
  s().addVariable(variable('Q', 'BOOL', { varClass: 'output' }), latch);
  const latchNet = pouByName(s().project, 'Latch').networks[0]!.id;
  s().placeElement(latchNet, { row: 0, col: 0 }, { kind: 'contact', contact: 'NO', variable: 'Set' });
  s().placeElement(latchNet, { row: 0, col: 1 }, { kind: 'coil', coil: 'SET', variable: 'Q' });
  s().placeElement(latchNet, { row: 1, col: 0 }, { kind: 'contact', contact: 'NO', variable: 'Reset' });
  s().placeElement(latchNet, { row: 1, col: 1 }, { kind: 'coil', coil: 'RESET', variable: 'Q' });

  const scale = s().addPou('FUNCTION', 'Scale', 'ST')!;
  s().updatePou(scale, { returnType: 'REAL' });
  s().addVariable(variable('Raw', 'INT', { varClass: 'input' }), scale);
  s().setPouSource(scale, 'Scale := INT_TO_REAL(Raw) * 0.1;', 'Edit ST body of Scale');

  const hyst = s().addPou('FUNCTION_BLOCK', 'TankHysteresis', 'ST')!;
  s().addVariable(variable('In', 'REAL', { varClass: 'input' }), hyst);
  s().addVariable(variable('Low', 'REAL', { varClass: 'input' }), hyst);
  s().addVariable(variable('High', 'REAL', { varClass: 'input' }), hyst);
  s().addVariable(variable('Q', 'BOOL', { varClass: 'output' }), hyst);
  s().addVariable(variable('L', 'Latch'), hyst);
  s().setPouSource(
    hyst,
    'L(Set := In > High, Reset := In < Low);\nQ := L.Q;',
    'Edit ST body of TankHysteresis',
  );

  s().setActivePou(main);
  s().addVariable(variable('RawIn', 'INT'));
  s().addVariable(variable('Level', 'REAL'));
  s().addVariable(variable('Pump', 'BOOL'));
  s().addVariable(variable('H1', 'TankHysteresis'));
  const net = pouByName(s().project, 'Main').networks[0]!.id;
  s().placeElement(
    net,
    { row: 0, col: 0 },
    { kind: 'box', blockType: 'Scale', inputs: { Raw: 'RawIn' }, outputs: { OUT: 'Level' } },
  );
  const net2 = s().addNetwork();
  s().placeElement(
    net2,
    { row: 0, col: 0 },
    {
      kind: 'box',
      blockType: 'TankHysteresis',
      instance: 'H1',
      inputs: { In: 'Level', Low: '20.0', High: '80.0' },
      outputs: { Q: 'Pump' },
    },
  );
  return store;
}

describe('ST POUs in the document', () => {
  test('a new POU in ST: an empty body, no networks; the palette lists it with its pins at once; Undo removes it', () => {
    const store = createDocumentStore(newProject('P'));
    const s = () => store.getState();
    const id = s().addPou('FUNCTION_BLOCK', 'Filter', 'ST')!;
    const pou = pouByName(s().project, 'Filter');
    expect(pou).toMatchObject({ id, kind: 'FUNCTION_BLOCK', language: 'ST', source: '', networks: [] });
    expect(s().activePouId).toBe(id);
    s().addVariable(variable('IN', 'REAL', { varClass: 'input' }), id);
    s().addVariable(variable('OUT', 'REAL', { varClass: 'output' }), id);
    const block = selectLibrary(s()).userBlocks.find((b) => b.name === 'Filter');
    expect(block?.kind).toBe('fb');
    expect(block?.inputs.map((p) => `${p.name}:${p.type}`)).toEqual(['IN:REAL']);
    expect(block?.outputs.map((p) => `${p.name}:${p.type}`)).toEqual(['OUT:REAL']);
    s().undo();
    s().undo();
    s().undo();
    expect(s().project.pous.some((p) => p.name === 'Filter')).toBe(false);
    // LD stays the default.
    s().addPou('PROGRAM', 'Second');
    expect(pouByName(s().project, 'Second')).toMatchObject({ language: 'LD' });
    expect(pouByName(s().project, 'Second').networks).toHaveLength(1);
  });

  test('the body text is one named undo step per edit; undo and redo restore it; an LD POU has no text body', () => {
    const store = createDocumentStore(newProject('P'));
    const s = () => store.getState();
    const main = s().activePouId;
    const id = s().addPou('FUNCTION', 'Scale', 'ST')!;
    expect(s().setPouSource(id, 'Scale := TRUE;', 'Edit ST body of Scale')).toBe(true);
    expect(s().undoName).toBe('Edit ST body of Scale');
    expect(s().setPouSource(id, 'Scale := TRUE;', 'Edit ST body of Scale')).toBe(false);
    s().setPouSource(id, 'Scale := FALSE;', 'Edit ST body of Scale');
    s().undo();
    expect(pouByName(s().project, 'Scale').source).toBe('Scale := TRUE;');
    s().undo();
    expect(pouByName(s().project, 'Scale').source).toBe('');
    s().redo();
    s().redo();
    expect(pouByName(s().project, 'Scale').source).toBe('Scale := FALSE;');
    expect(s().setPouSource(main, 'x := 1;', 'Edit')).toBe(false);
    expect(pouByName(s().project, 'Main').source).toBeUndefined();
  });
});

describe('calls both ways, run', () => {
  test('LD calls the ST FUNCTION and the ST FB with their pins; the ST FB calls an LD FB', () => {
    const project = plant().getState().project;
    const { program, diagnostics } = compileProgram(project, {});
    expect(diagnostics.filter((d) => d.severity === 'error').map(formatDiagnostic)).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 10 });
    const read = () => [plc.read('Level'), plc.read('Pump'), plc.read('H1.L.Q')];
    plc.write('RawIn', 500);
    plc.scan();
    expect(read()).toEqual([50, false, false]);
    plc.write('RawIn', 900);
    plc.scan();
    expect(read()).toEqual([90, true, true]);
    // Inside the band the latch holds; below Low it resets.
    plc.write('RawIn', 500);
    plc.scan();
    expect(read()).toEqual([50, true, true]);
    plc.write('RawIn', 100);
    plc.scan();
    expect(read()).toEqual([10, false, false]);
  });

  test('a body with a syntax error does not compile: LD-E50 names the POU, line and column; Run is refused', () => {
    const store = plant();
    const s = () => store.getState();
    s().setPouSource(
      pouByName(s().project, 'Scale').id,
      'Scale := INT_TO_REAL(Raw) *\n  ;',
      'Edit ST body of Scale',
    );
    const { program, diagnostics } = compileProgram(s().project, {});
    expect(program).toBeUndefined();
    const e50 = diagnostics.filter((d) => d.rule === 'LD-E50');
    expect(e50).toHaveLength(1);
    expect(e50[0]!.message).toMatch(/ST body of Scale does not compile: line 2 col 3/);

    const { transport, scheduler } = loopback();
    const sim = createSimStore(transport);
    sim.getState().run(s().project);
    scheduler.advance(30);
    expect(sim.getState().mode).toBe('stopped');
    expect(sim.getState().refusal?.diagnostics.map((d) => d.rule)).toContain('LD-E50');
  });

  test('online, an ST body edit applies as you edit; a broken body never runs: the running program stays', () => {
    const store = plant();
    const s = () => store.getState();
    const { transport, scheduler } = loopback();
    const sim = createSimStore(transport);
    const level = () => sim.getState().values[sim.getState().variableIndex.get('LEVEL')!];
    sim.getState().run(s().project);
    scheduler.advance(30);
    expect(sim.getState().mode).toBe('running');
    sim.getState().write('RawIn', { value: 500 });
    scheduler.advance(30);
    expect(level()).toBe(50);

    const scale = pouByName(s().project, 'Scale').id;
    s().setPouSource(scale, 'Scale := INT_TO_REAL(Raw) * ;', 'Edit ST body of Scale');
    sim.getState().documentChanged(s().project);
    scheduler.advance(60);
    expect(sim.getState().mode).toBe('running');
    expect(level()).toBe(50);
    expect(sim.getState().refusal?.diagnostics.map((d) => d.rule)).toContain('LD-E50');

    s().setPouSource(scale, 'Scale := INT_TO_REAL(Raw) * 0.2;', 'Edit ST body of Scale');
    sim.getState().documentChanged(s().project);
    scheduler.advance(60);
    expect(sim.getState().onlineChange?.kind).toBe('applied');
    expect(level()).toBe(100);
  });
});
