// `rungsmith simulate` with STRING variables: a STRING column in --inputs (plain text, quoted cells,
// IEC literals) and STRING values in the output CSV quoted per RFC 4180.
import { describe, expect, it } from 'vitest';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { saveProject } from '../../src/model/load';
import { readCsv } from '../../src/sim/csv';
import { rungsmith } from './memoryIo';

/** Msg := CONCAT(Name, ', ok'); N := LEN(Name). */
function project(scenarios: { name: string; csv: string }[] = []): string {
  const box = (id: string, row: number, blockType: string, inputs: Record<string, string>, outputs: Record<string, string>) => ({
    id: id as ElementId,
    kind: 'box' as const,
    row,
    col: 1,
    blockType,
    inputs,
    outputs,
  });
  const net = (b: ReturnType<typeof box>) =>
    newNetwork({ rows: 4, cols: 4, elements: [{ id: `l${b.id}` as ElementId, kind: 'link', row: 0, col: 0 }, b], vlinks: [] });
  const main = newPou('Main', {
    variables: [variable('Name', 'STRING', { initial: "'start'" }), variable('Msg', 'STRING'), variable('N', 'INT')],
    networks: [
      net(box('b1', 0, 'CONCAT', { IN1: 'Name', IN2: "', ok'" }, { OUT: 'Msg' })),
      net(box('b2', 0, 'LEN', { IN: 'Name' }, { OUT: 'N' })),
    ],
  });
  return saveProject({ ...newProject('S', { pous: [main] }), scenarios });
}

describe('rungsmith simulate with STRING', () => {
  it('reads STRING cells as text or literals and writes them back quoted where needed', () => {
    const stim = [
      'scan,Name',
      '2,Pump 1',
      '3,"a ""quoted"" name"',
      "4,'two$Nlines'",
      "5,''",
    ].join('\n');
    const r = rungsmith(['simulate', 'p.json', '--inputs', 'stim.csv', '--scans', '5', '--watch', 'Name,Msg,N'], {
      'p.json': project(),
      'stim.csv': stim,
    });
    expect(r.err).toBe('');
    expect(r.code).toBe(0);
    const lines = r.out.trim().split('\n');
    expect(lines[1]).toBe('1,0,start,"start, ok",5');
    expect(lines[2]).toBe('2,10,Pump 1,"Pump 1, ok",6');
    expect(lines[3]).toBe('3,20,"a ""quoted"" name","a ""quoted"" name, ok",15');
    // A line break (and an empty string) is written as the IEC literal, which reads back the same.
    expect(lines[4]).toBe(`4,30,'two$Nlines',"'two$Nlines, ok'",9`);
    expect(lines[5]).toBe("5,40,'',\", ok\",0");
    expect(readCsv(r.out).rows[3]!.cells).toEqual(['3', '20', 'a "quoted" name', 'a "quoted" name, ok', '15']);
  });

  it('names the file, line and column of a bad STRING cell', () => {
    const r = rungsmith(['simulate', 'p.json', '--inputs', 'stim.csv'], {
      'p.json': project(),
      'stim.csv': "scan,Name\n2,'unclosed$'\n",
    });
    expect(r.code).not.toBe(0);
    expect(r.err).toMatch(/stim\.csv line 2, column Name: .*\$/);
  });

  it('rungsmith test checks STRING expectations exactly', () => {
    const csv = "scan,Name,expect Msg,expect N\n1,Pump,\"Pump, ok\",4\n2,'',\"', ok'\",0\n";
    const pass = rungsmith(['test', 'p.json'], { 'p.json': project([{ name: 'strings', csv }]) });
    expect(pass.out).toMatch(/^PASS strings/m);
    expect(pass.code).toBe(0);
    const wrong = csv.replace('"Pump, ok"', '"Pump ok"');
    const fail = rungsmith(['test', 'p.json'], { 'p.json': project([{ name: 'strings', csv: wrong }]) });
    expect(fail.code).toBe(1);
    expect(fail.out).toContain("Msg expected 'Pump ok', got 'Pump, ok'");
  });
});
