// Libraries kept with the project (docs/libraries.md): reading a PLCopen file or a Rungsmith project
// as a library, add (hash, clash refusal), blocks resolving and running, update (what changes, uses
// of removed blocks as located errors), remove (refused while used), save and load.
import { readFileSync } from 'node:fs';
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { addLibrary, libraryHash, libraryUses, removeLibrary, updateLibrary, withLibraries } from '../../src/model/libraries';
import { blockLibrary } from '../../src/model/library';
import { loadProject, saveProject } from '../../src/model/load';
import type { Project, ProjectLibrary } from '../../src/model/project';
import { readLibraryFile } from '../../src/plcopen/libraryFile';
import { pouNameProblem } from '../../src/store/pouEdits';
import { ladder, plcOf, trace, vars, type BoxSpec } from '../engine/ladder';
import { multiProject, pou } from '../engine/userBlocksHelpers';

const fixture = (name: string) => readFileSync(new URL(`../fixtures/libraries/${name}`, import.meta.url), 'utf8');
const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });
const NOW = new Date('2026-11-28T12:00:00Z');

async function conveyors(file = 'conveyors.xml'): Promise<ProjectLibrary> {
  const read = await readLibraryFile(file, fixture(file), NOW);
  if (!read.ok) throw new Error(read.errors.join('\n'));
  return read.library;
}

/** Main: Belt (Conveyor) started by Go, stopped by Halt; Scaled := Scale(Raw, 3). */
const main = () =>
  pou('Main', 'PROGRAM', vars('Go BOOL', 'Halt BOOL', 'Moving BOOL', 'Raw INT', 'Scaled INT', 'Belt Conveyor'), [
    ladder(['[Go] # # (Moving)', '. # # .', '. # # .'], { boxes: [box('Conveyor', 0, 1, { instance: 'Belt', inputs: { Stop: 'Halt' } })] }),
    ladder(['. # # .', '. # # .', '. # # .'], { boxes: [box('Scale', 0, 1, { inputs: { Value: 'Raw', Factor: '3' }, outputs: { OUT: 'Scaled' } })] }),
  ]);

async function projectWithLibrary(): Promise<Project> {
  const added = addLibrary(multiProject([main()]), await conveyors());
  if (!added.ok) throw new Error(added.errors.join('\n'));
  return added.project;
}

describe('reading a file as a library', () => {
  test('a PLCopen file gives its FBs, functions and data types, versioned by the SHA-256 of the file; programs are left out', async () => {
    const read = await readLibraryFile('conveyors.xml', fixture('conveyors.xml'), NOW);
    expect(read.ok).toBe(true);
    if (!read.ok) return;
    const lib = read.library;
    expect(lib.name).toBe('Conveyors');
    expect(lib.sourceFile).toBe('conveyors.xml');
    expect(lib.addedAt).toBe('2026-11-28T12:00:00.000Z');
    expect(lib.origin).toBe('plcopen');
    expect(lib.pous.map((p) => `${p.kind} ${p.name}`)).toEqual(['FUNCTION_BLOCK Conveyor', 'FUNCTION Scale']);
    expect(lib.dataTypes?.map((d) => d.name)).toEqual(['BeltSpeed']);
    // sha256 of the file's bytes, as `sha256sum` prints it.
    const { createHash } = await import('node:crypto');
    expect(lib.hash).toBe(`sha256:${createHash('sha256').update(fixture('conveyors.xml')).digest('hex')}`);
    expect(read.notes.join('\n')).toMatch(/PROGRAM \(Demo\).*left out/);
    // A different file is a different version.
    expect((await conveyors('conveyors-v2.xml')).hash).not.toBe(lib.hash);
  });

  test('a Rungsmith project file gives its FBs and functions', async () => {
    const source = multiProject([main(), pou('Blinker', 'FUNCTION_BLOCK', vars('Q BOOL').map((v) => ({ ...v, varClass: 'output' as const })), [])]);
    const read = await readLibraryFile('blinkers.rungsmith.json', saveProject(source), NOW, 'Blinkers');
    expect(read.ok && read.library.pous.map((p) => p.name)).toEqual(['Blinker']);
    expect(read.ok && read.library.origin).toBe('rungsmith');
  });

  test('a file that is neither gives a clear error; a broken PLCopen file a located one', async () => {
    const bad = await readLibraryFile('notes.txt', 'hello', NOW);
    expect(bad.ok ? [] : bad.errors).toEqual(['notes.txt is neither a PLCopen XML file nor a Rungsmith project file']);
    const broken = await readLibraryFile('broken.xml', '<project xmlns="http://www.plcopen.org/xml/tc6_0201">\n<types>\n</project>', NOW);
    expect(broken.ok ? '' : broken.errors[0]).toMatch(/^broken\.xml, line \d+: not well-formed XML/);
  });
});

describe('the version hash without Web Crypto (plain http on a plant network)', () => {
  test('libraryHash gives the digest node:crypto gives, across block boundaries and for UTF-8 text', async () => {
    const { createHash } = await import('node:crypto');
    const texts = ['', 'abc', 'a'.repeat(55), 'a'.repeat(56), 'a'.repeat(64), 'Förderband ⚙ 🏭\n'.repeat(37), fixture('conveyors.xml')];
    for (const t of texts) expect(await libraryHash(t)).toBe(`sha256:${createHash('sha256').update(t).digest('hex')}`);
  });
});

describe('a library in the project', () => {
  test('its blocks resolve like the project’s own POUs and run in the simulator', async () => {
    const project = await projectWithLibrary();
    const lib = blockLibrary(project);
    expect(lib.libraryBlocks.map((b) => `${b.library}:${b.name}`)).toEqual(['Conveyors:Conveyor', 'Conveyors:Scale']);
    expect(lib.isFbType('Conveyor')).toBe(true);
    expect(lib.userBlocks.map((b) => b.name)).toEqual([]);
    expect(checkProject(project).filter((d) => d.severity === 'error')).toEqual([]);
    const plc = plcOf(project);
    // Moving is the box's first BOOL output (Running) carried on to the coil.
    const rows = trace(plc, [{ Go: true, Raw: 7 }, { Go: false }, { Halt: true }, { Halt: false, Go: true }], ['Moving', 'Belt.Running', 'Belt.Starts', 'Scaled']);
    expect(rows).toEqual([
      [1, 1, 1, 21],
      [1, 1, 1, 21],
      [0, 0, 1, 21],
      [1, 1, 2, 21],
    ]);
  });

  test('an ST program calls them too', async () => {
    const st = { ...pou('Main', 'PROGRAM', vars('Go BOOL', 'Out INT', 'Belt Conveyor'), []), language: 'ST' as const, source: 'Belt(Start := Go, Stop := FALSE);\nOut := Scale(Value := 2, Factor := 5);\n' };
    const added = addLibrary(multiProject([st]), await conveyors());
    if (!added.ok) throw new Error(added.errors.join('\n'));
    expect(checkProject(added.project).filter((d) => d.severity === 'error')).toEqual([]);
    expect(trace(plcOf(added.project), [{ Go: false }, { Go: true }], ['Belt.Running', 'Belt.Starts', 'Out'])).toEqual([
      [0, 0, 10],
      [1, 1, 10],
    ]);
  });

  test('adding refuses name clashes with the project’s POUs, other libraries and standard blocks, with the reason', async () => {
    const lib = await conveyors();
    const clash = addLibrary(multiProject([main(), pou('Scale', 'FUNCTION', [], [], 'INT')]), lib);
    expect(clash.ok ? [] : clash.errors).toEqual(['function Scale clashes with the function Scale of the project; rename one of them first']);
    const project = await projectWithLibrary();
    const again = addLibrary(project, { ...lib, name: 'Belts' });
    expect(again.ok ? [] : again.errors).toEqual([
      'function block Conveyor is already defined by the library Conveyors',
      'function Scale is already defined by the library Conveyors',
      'data type BeltSpeed is already defined by the library Conveyors',
    ]);
    const sameName = addLibrary(project, { ...lib, pous: [], dataTypes: [{ name: 'Other', def: { kind: 'alias', base: 'INT' } }] });
    expect(sameName.ok ? [] : sameName.errors).toEqual(['the project already has a library named Conveyors; remove it, update it, or give this one another name']);
    const standard = addLibrary(multiProject([main()]), { ...lib, pous: [{ ...lib.pous[0]!, name: 'TON' }] });
    expect(standard.ok ? [] : standard.errors[0]).toMatch(/TON has the name of the standard function block TON/);
  });

  test('a POU named like a library block (a file opened as it was) is LD-E25, naming the library; the editor refuses such a name', async () => {
    const project = await projectWithLibrary();
    const renamed = { ...project, pous: [...project.pous, pou('Scale', 'FUNCTION', [], [], 'INT')] };
    expect(checkProject(renamed).find((d) => d.rule === 'LD-E25')?.message).toMatch(/Scale of the project is also a block of the library Conveyors/);
    // The editor refuses the name when a POU is added or renamed.
    expect(pouNameProblem(project, 'scale')).toBe('"scale" is a block or data type of the library Conveyors.');
  });

  test('removing is refused while POUs use its blocks, with every use; allowed once unused', async () => {
    const project = await projectWithLibrary();
    const refused = removeLibrary(project, 'Conveyors');
    expect(refused.ok).toBe(false);
    if (refused.ok) return;
    expect(refused.uses.map((u) => [u.pou, u.name, u.network ?? u.variable])).toEqual([
      ['Main', 'Conveyor', 'Belt'],
      ['Main', 'Conveyor', 1],
      ['Main', 'Scale', 2],
    ]);
    const unused = { ...project, pous: [pou('Main', 'PROGRAM', vars('Go BOOL'), [])] };
    const removed = removeLibrary(unused, 'Conveyors');
    expect(removed.ok && removed.project.libraries).toBe(undefined);
  });

  test('uses in ST bodies are found (comments aside)', async () => {
    const project = await projectWithLibrary();
    const st = { ...pou('Other', 'PROGRAM', [], []), language: 'ST' as const, source: '(* Scale here is a comment *)\nX := Scale(Value := 1, Factor := 2);' };
    expect(libraryUses({ ...project, pous: [st] }, 'Conveyors')).toEqual([{ pou: 'Other', name: 'Scale', line: 2 }]);
  });

  test('an update shows blocks added, removed and changed; uses of a removed block become located LD-E01 errors', async () => {
    const project = await projectWithLibrary();
    const v2 = await conveyors('conveyors-v2.xml');
    const update = updateLibrary(project, 'Conveyors', v2);
    expect(update.ok).toBe(true);
    if (!update.ok) return;
    expect(update.same).toBe(false);
    expect(update.diff.added).toEqual(['Scale2']);
    expect(update.diff.removed).toEqual(['Scale']);
    expect(update.diff.changed).toEqual([
      {
        name: 'Conveyor',
        was: 'FUNCTION_BLOCK Conveyor (Start : BOOL; Stop : BOOL -> Running : BOOL; Starts : INT)',
        now: 'FUNCTION_BLOCK Conveyor (Start : BOOL; Stop : BOOL; Jog : BOOL -> Running : BOOL; Starts : INT)',
      },
    ]);
    expect(update.affected.map((u) => `${u.pou} ${u.name} ${u.network ?? u.variable}`)).toEqual(['Main Conveyor Belt', 'Main Conveyor 1', 'Main Scale 2']);
    const lib = update.project.libraries![0]!;
    expect([lib.name, lib.hash]).toEqual(['Conveyors', v2.hash]);
    const errors = checkProject(update.project).filter((d) => d.severity === 'error');
    expect(errors).toHaveLength(1);
    // At the Scale box of the second network (0-based network 1).
    expect(errors[0]).toMatchObject({ rule: 'LD-E01', pou: 'Main', network: 1, elementId: update.project.pous[0]!.networks[1]!.elements.find((e) => e.kind === 'box')!.id });
    expect(errors[0]!.message).toMatch(/uses "Scale", which is not a standard function or function block nor a FUNCTION or FUNCTION_BLOCK of the project nor a block of its libraries \(Conveyors\)$/);
    // The same file again: nothing changes.
    const same = updateLibrary(project, 'Conveyors', await conveyors());
    expect(same.ok && [same.same, same.diff.added, same.diff.removed, same.diff.changed]).toEqual([true, [], [], []]);
  });

  test('an update whose new block clashes with a project POU is refused', async () => {
    const project = await projectWithLibrary();
    const withScale2 = { ...project, pous: [...project.pous, pou('Scale2', 'FUNCTION', [], [], 'INT')] };
    const update = updateLibrary(withScale2, 'Conveyors', await conveyors('conveyors-v2.xml'));
    expect(update.ok ? [] : update.errors).toEqual(['function Scale2 clashes with the function Scale2 of the project; rename one of them first']);
  });

  test('the library is saved in the project file and loads back the same; the engine compiles it with the project', async () => {
    const project = await projectWithLibrary();
    const loaded = loadProject(saveProject(project));
    expect(loaded.ok).toBe(true);
    if (!loaded.ok) return;
    expect(loaded.project.libraries).toEqual(project.libraries);
    expect(withLibraries(loaded.project).pous.map((p) => p.name)).toEqual(['Main', 'Conveyor', 'Scale']);
    expect(blockLibrary(withLibraries(loaded.project)).all().filter((b) => b.name === 'Conveyor')).toHaveLength(1);
    const twice = JSON.parse(saveProject(project)) as { libraries: unknown[] };
    twice.libraries.push(twice.libraries[0]);
    const dup = loadProject(JSON.stringify(twice));
    expect(dup.ok ? [] : dup.errors.map((e) => e.message)).toContain('duplicate library "Conveyors"');
  });
});
