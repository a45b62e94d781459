// `rungsmith export` says on stderr what Beremiz/OpenPLC would run differently (LD-X rules).
import { describe, expect, it } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { saveProject } from '../../src/model/load';
import { rungsmith } from './memoryIo';
import { ladder, project, vars } from '../engine/ladder';

const example = (id: string) => saveProject(EXAMPLES.find((e) => e.id === id)!.build());

describe('rungsmith export warnings', () => {
  it('names the dropped jump by rule, POU, network and cell; the XML is still written and the exit code is 0', () => {
    const r = rungsmith(['export', 'j.json', '-o', 'j.xml'], { 'j.json': example('jump-label') });
    expect(r.code).toBe(0);
    expect(r.files.get('j.xml')).toContain('<jump ');
    expect(r.err.trim().split('\n')).toEqual([
      expect.stringMatching(/^warning LD-X01 Main\/network 1:R1C10 Beremiz and OpenPLC drop the jump to "MAINT" .*network 2, which it skips when it is powered here, runs in every scan there/),
    ]);
  });

  it('offers the coil fix for the traffic light timers whose Q reaches only the right rail', () => {
    const r = rungsmith(['export', 't.json'], { 't.json': example('traffic-light') });
    expect(r.code).toBe(0);
    expect(r.out).toContain('<project');
    const lines = r.err.trim().split('\n');
    expect(lines).toHaveLength(2);
    expect(lines[0]).toMatch(/^warning LD-X03 Main\/network 1:R1C3 the TON block "RedTime": .*networks 4 and 5 sees them one scan late\..* Fix: Add a coil "RedTime_Q" on output Q of TON "RedTime"\.$/);
    expect(lines[1]).toMatch(/^warning LD-X03 Main\/network 2:R1C3 the TON block "GreenTime"/);
  });

  it('prints nothing on stderr for a program Beremiz runs the same way', () => {
    const r = rungsmith(['export', 'm.json', '-o', 'm.xml'], { 'm.json': example('motor-start-stop') });
    expect(r).toMatchObject({ code: 0, err: '' });
  });

  it('names the generator bugs Beremiz and OpenPLC would compile: a connector OR without brackets, coils in series after an OR join', () => {
    const p = project(vars('I1 BOOL %IX0.1', 'I2 BOOL %IX0.2', 'I3 BOOL %IX0.3', 'Q0 BOOL %QX0.0', 'Q1 BOOL', 'Q2 BOOL'), [
      ladder(['+ [I1] + >CX>|', '+ [I2] +', '|>CX> [I3] (Q0)']),
      ladder(['+ [I1] + (Q1) (Q2)', '+ [I2] +']),
    ]);
    const r = rungsmith(['export', 'c.json', '-o', 'c.xml'], { 'c.json': saveProject(p) });
    expect(r.code).toBe(0);
    expect(r.files.get('c.xml')).toContain('<connector ');
    expect(r.err.trim().split('\n')).toEqual([
      expect.stringMatching(/^warning LD-X06 Main\/network 1:R3C1 .*connector ">CX>".*Q0 := I3 AND I1 OR I2/),
      expect.stringMatching(/^warning LD-X07 Main\/network 2:R1C2 the coil "Q1" joins 2 branches \(I1 OR I2\), and the coil "Q2" follows it in series/),
    ]);
  });
});
