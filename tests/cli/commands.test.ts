// `rungsmith check`, `export`, `import`, help and exit codes.
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { loadProject, saveProject } from '../../src/model/load';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { rungsmith } from './memoryIo';

const motor = saveProject(EXAMPLES[0]!.build());
const fixture = (name: string) =>
  readFileSync(fileURLToPath(new URL(`../fixtures/plcopen/${name}`, import.meta.url)), 'utf8');

function broken(): string {
  const p = JSON.parse(motor);
  p.pous[0].networks[0].elements.push({
    id: 'x1',
    kind: 'coil',
    coil: 'COIL',
    variable: 'Lamp',
    row: 1,
    col: 9,
  });
  return JSON.stringify(p);
}

describe('rungsmith check', () => {
  it('prints nothing and exits 0 for a correct program', () => {
    expect(rungsmith(['check', 'm.json'], { 'm.json': motor })).toMatchObject({ code: 0, out: '' });
  });

  it('prints SEVERITY RULE-ID pou/network:cell message per diagnostic and exits 1 on an error', () => {
    const r = rungsmith(['check', 'b.json'], { 'b.json': broken() });
    expect(r.code).toBe(1);
    const lines = r.out.trim().split('\n');
    expect(lines.length).toBeGreaterThan(0);
    for (const l of lines)
      expect(l).toMatch(/^(error|warning) LD-[RWE]\d+ Main\/(network \d+(:R\d+C\d+)?|variables) \S/);
    expect(lines.some((l) => l.includes('"Lamp"'))).toBe(true);
  });

  it('checks PLCopen files too (import findings on stderr, diagnostics on stdout)', () => {
    const r = rungsmith(['check', 'c.xml'], { 'c.xml': fixture('codesys-zero-geometry.xml') });
    expect(r.code).toBe(0);
    expect(r.out).toBe('');
    expect(r.err).toContain('warning: line 2 <project>: PLCopen TC6 v2.0 namespace');
  });

  it('exits 2 with a located message for unreadable or invalid input', () => {
    expect(rungsmith(['check', 'missing.json'])).toMatchObject({
      code: 2,
      err: 'rungsmith: cannot read missing.json: ENOENT\n',
    });
    const bad = rungsmith(['check', 'x.xml'], {
      'x.xml': '<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types>',
    });
    expect(bad.code).toBe(2);
    expect(bad.err).toMatch(/x\.xml: line 1: not well-formed XML/);
    expect(
      rungsmith(['check', 'p.json'], { 'p.json': '{"format":"rungsmith-project","version":1}' }).err,
    ).toContain('p.json: name');
  });
});

describe('rungsmith export and import', () => {
  it('export writes PLCopen XML to -o, import reads it back to an equivalent project JSON', () => {
    const ex = rungsmith(['export', 'm.json', '-o', 'm.xml'], { 'm.json': motor });
    expect(ex.code).toBe(0);
    const xml = ex.files.get('m.xml')!;
    expect(xml).toContain('<project xmlns="http://www.plcopen.org/xml/tc6_0201"');
    const im = rungsmith(['import', 'm.xml', '-o', 'back.json'], { 'm.xml': xml });
    expect(im.code).toBe(0);
    expect(im.err).toBe(
      'imported 1 LD POU: Main (1 network); 0 warnings\n' +
        'semantics profile iec, as recorded by Rungsmith in the file (rungsmith simulate --profile overrides it)\n',
    );
    const back = loadProject(im.files.get('back.json')!);
    expect(back.ok && back.project.pous[0]!.variables).toEqual(EXAMPLES[0]!.build().pous[0]!.variables);
  });

  it('without -o they write to stdout', () => {
    const out = rungsmith(['export', 'm.json'], { 'm.json': motor }).out;
    expect(importPlcopen(out).ok).toBe(true);
    const json = rungsmith(['import', 'j.xml'], { 'j.xml': fixture('jump-label-return.xml') }).out;
    expect(loadProject(json).ok).toBe(true);
  });

  it('import lists what it changed on stderr', () => {
    const r = rungsmith(['import', 'a.xml', '-o', 'a.json'], { 'a.xml': fixture('adddata.xml') });
    expect(r.code).toBe(0);
    expect(r.err).toContain('addData "http://example.com/acme/cache" dropped');
  });
});

describe('rungsmith usage', () => {
  it.each(['check', 'simulate', 'export', 'import'])('%s --help explains the command and exits 0', (cmd) => {
    const r = rungsmith([cmd, '--help']);
    expect(r.code).toBe(0);
    expect(r.out).toContain(`Usage: rungsmith ${cmd}`);
  });

  it('no command prints the overview and exits 2; unknown commands and options exit 2', () => {
    expect(rungsmith([])).toMatchObject({ code: 2 });
    expect(rungsmith(['--help']).out).toContain('Commands:');
    expect(rungsmith(['frobnicate']).err).toContain('unknown command "frobnicate"');
    expect(rungsmith(['check', '--fast', 'x.json']).code).toBe(2);
    expect(rungsmith(['simulate', 'm.json', '--scans', 'many'], { 'm.json': motor }).err).toContain(
      '--scans "many"',
    );
    expect(rungsmith(['simulate', 'm.json', '--profile', 'siemens'], { 'm.json': motor }).err).toContain(
      '--profile must be iec or openplc',
    );
  });

  it('runs as a real process through bin/rungsmith.mjs (as npx rungsmith does)', () => {
    const bin = fileURLToPath(new URL('../../bin/rungsmith.mjs', import.meta.url));
    const file = fileURLToPath(new URL('../fixtures/plcopen/jump-label-return.xml', import.meta.url));
    const r = spawnSync(process.execPath, [bin, 'simulate', file, '--scans', '2', '--watch', 'A,B'], {
      encoding: 'utf8',
      timeout: 60_000,
    });
    expect(r.status).toBe(0);
    expect(r.stdout).toBe('scan,time_ms,A,B\n1,0,1,1\n2,5,1,1\n');
  });

  it('piped into a reader that stops early (| head), it ends quietly with its own exit code, no EPIPE stack trace', () => {
    const bin = fileURLToPath(new URL('../../bin/rungsmith.mjs', import.meta.url));
    const file = fileURLToPath(new URL('../fixtures/plcopen/jump-label-return.xml', import.meta.url));
    // 60,000 rows are far more than a pipe holds: the writes after head exits fail with EPIPE.
    const script = `"${process.execPath}" "${bin}" simulate "${file}" --scans 60000 --watch A,B | head -n 2; echo "status \${PIPESTATUS[0]}"`;
    const r = spawnSync('/bin/bash', ['-c', script], { encoding: 'utf8', timeout: 120_000 });
    expect(r.stderr).not.toContain('EPIPE');
    // Only the program's own warnings (its jump and RETURN under openplc), no stack trace.
    expect(r.stderr.trim().split('\n').every((l) => l.startsWith('warning LD-W'))).toBe(true);
    expect(r.stdout).toBe('scan,time_ms,A,B\n1,0,1,1\nstatus 0\n');
  });
});
