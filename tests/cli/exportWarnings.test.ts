// `rungsmith export` says on stderr what Beremiz/OpenPLC would run differently (LD-X rules).
import { describe, expect, it } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { saveProject } from '../../src/model/load';
import { rungsmith } from './memoryIo';

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
});
