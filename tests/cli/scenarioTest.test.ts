// `rungsmith test`: scenarios stored in a project run headless; PASS/FAIL, the first divergent scan
// with "Why?", a summary, exit 1 on failure and JUnit XML for CI.
import { describe, expect, it } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { saveProject } from '../../src/model/load';
import type { Project } from '../../src/model/project';
import { rungsmith } from './memoryIo';

const example = (id: string): Project => EXAMPLES.find((e) => e.id === id)!.build();
const file = (p: Project) => ({ 'p.json': saveProject(p) });

describe('rungsmith test', () => {
  it('passes the example scenarios of the motor and traffic-light examples', () => {
    for (const id of ['motor-start-stop', 'traffic-light']) {
      const r = rungsmith(['test', 'p.json'], file(example(id)));
      expect(r.err).toBe('');
      expect(r.out).toMatch(/^PASS /m);
      expect(r.out).toMatch(/^1 passed, 0 failed \(1 scenario of /m);
      expect(r.code).toBe(0);
    }
  });

  it('fails after an edit that breaks the program, naming the scan, the values and why', () => {
    const p = example('motor-start-stop');
    // The seal-in contact is deleted: Motor drops out when Start is released.
    const net = p.pous[0]!.networks[0]!;
    const broken: Project = {
      ...p,
      pous: [{ ...p.pous[0]!, networks: [{ ...net, elements: net.elements.filter((e) => !(e.kind === 'contact' && e.variable === 'Motor')), vlinks: [] }] }],
    };
    const r = rungsmith(['test', 'p.json', '--junit', 'out.xml'], file(broken));
    expect(r.code).toBe(1);
    expect(r.out).toContain('FAIL Start seals in, Stop wins: scan 3 (line 5): Motor expected 1, got 0');
    expect(r.out).toContain('Why? Motor is FALSE after scan 3');
    expect(r.out).toContain('| | Start is open: Start is FALSE');
    expect(r.out).toMatch(/^0 passed, 1 failed/m);
    const junit = r.files.get('out.xml')!;
    expect(junit).toContain('<testsuite name="Motor start/stop" tests="1" failures="1"');
    expect(junit).toContain('<failure message="scan 3 (line 5): Motor expected 1, got 0">');
  });

  it('checks TIME within a tolerance and treats * and empty cells as don\'t care', () => {
    const p = example('traffic-light');
    const scenario = (et: string) => ({ name: 'et', csv: `# cycle: 100ms\nscan,expect RedTime.ET,expect Green\n26,${et},*\n30,,0\n` });
    expect(rungsmith(['test', 'p.json'], file({ ...p, scenarios: [scenario('2450~50')] })).code).toBe(0);
    const off = rungsmith(['test', 'p.json'], file({ ...p, scenarios: [scenario('2400~50')] }));
    expect(off.code).toBe(1);
    expect(off.out).toContain('RedTime.ET expected 2400 ± 50, got 2500');
  });

  it('reports a scenario it cannot read with its line, and a project without scenarios', () => {
    const p = example('motor-start-stop');
    const bad = rungsmith(['test', 'p.json'], file({ ...p, scenarios: [{ name: 'typo', csv: 'scan,Strat,expect Motor\n1,1,1\n' }] }));
    expect(bad.code).toBe(1);
    expect(bad.out).toContain('FAIL typo: line 1: unknown variable "Strat"');
    const none = rungsmith(['test', 'p.json'], file({ ...p, scenarios: [] }));
    expect(none.code).toBe(1);
    expect(none.err).toContain('has no test scenarios');
    const unknown = rungsmith(['test', 'p.json', '--scenario', 'nope'], file(p));
    expect(unknown.code).toBe(2);
  });
});
