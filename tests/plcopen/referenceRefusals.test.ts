// Files the MATIEC reference itself refuses (the oracle of docs/CORPUS.md: Beremiz's generator or iec2c
// stops): Rungsmith refuses them too with an error naming the same fault, or runs them with what it
// cannot know kept external and named (issue 23 class 10). Each case below quotes what the reference
// printed for the file in tests/fixtures/reference-refused/.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { rungsmith } from '../cli/memoryIo';

const file = (name: string) =>
  readFileSync(fileURLToPath(new URL(`../fixtures/reference-refused/${name}`, import.meta.url)), 'utf8');
const check = (name: string) => rungsmith(['check', 'f.xml'], { 'f.xml': file(name) });
const simulate = (name: string) =>
  rungsmith(['simulate', 'f.xml', '--scans', '3', '--watch', 'Run', '--profile', 'openplc'], { 'f.xml': file(name) });

describe('files the reference refuses', () => {
  it('a WORD at a bit location (%IX0.3): refused, as iec2c does ("Bit size of data type is incompatible with bit size of location")', () => {
    const r = check('word-at-bit-location.xml');
    expect(r.code).toBe(1);
    expect(r.out).toContain('error LD-E13 Fan/variables the variable "Count" is WORD but its location %IX0.3 holds one bit (BOOL)');
  });

  it('EQ of a BOOL and an INT: refused, as iec2c does ("Unable to resolve which overloaded function EQ is being invoked")', () => {
    const r = check('eq-bool-int.xml');
    expect(r.code).toBe(1);
    expect(r.out).toContain('error LD-R11 Fan/network 1:R1C2 the EQ block at R1C2: EQ cannot compare BOOL and INT');
    expect(simulate('eq-bool-int.xml').err).toContain('the program Fan has errors; it cannot be simulated');
  });

  it('a block type nobody declares (the generator: "No informations found for block"): runs with the block external and named', () => {
    const r = simulate('unknown-vendor-block.xml');
    expect(r.code).toBe(0);
    expect(r.err).toContain('block type ACME_MAGIC is neither a standard block, nor a POU of this file, nor a block of a known vendor library');
    expect(r.err).toContain('warning LD-W10 Fan/network 1:R1C2 the ACME_MAGIC block "M1" is the external block ACME_MAGIC');
    expect(r.out.trim().split('\n')).toEqual(['scan,time_ms,Run', '1,0,0', '2,10,0', '3,20,0']);
  });

  it('two variables at one location: refused under openplc, as iec2c does ("invalid location in global location declaration")', () => {
    const r = rungsmith(['simulate', 'f.xml', '--scans', '1', '--profile', 'openplc'], { 'f.xml': file('two-variables-one-location.xml') });
    expect(r.code).toBe(1);
    expect(r.err).toContain('error LD-E17 Fan/variables the variable "Run2" shares the location %QX3.0 with "Run"');
    const iec = rungsmith(['simulate', 'f.xml', '--scans', '1', '--profile', 'iec'], { 'f.xml': file('two-variables-one-location.xml') });
    expect(iec.code).toBe(0);
    expect(iec.err).toContain('warning LD-W02');
  });

  it('a VAR_EXTERNAL with no global (iec2c: "The external variable does not match with any global variable"): runs, warning LD-W16 names MATIEC\'s fault', () => {
    const r = simulate('external-undeclared.xml');
    expect(r.code).toBe(0);
    expect(r.err).toContain('warning LD-W16 Fan/variables Run is declared outside the project');
    expect(r.err).toContain('"the external variable does not match with any global variable"');
  });
});
