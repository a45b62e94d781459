import { describe, expect, test } from 'vitest';
import { buildLayout, programFingerprint, readableNames } from '../../src/sim/layout';
import { appendTrend, emptyTrend } from '../../src/sim/trendBuffer';
import { motorProgram, threeNetworks, timerProgram } from './programs';

describe('trend window', () => {
  test('keeps only the last N scans', () => {
    let buffer = emptyTrend(['A']);
    buffer = appendTrend(buffer, { names: ['A'], scans: [1, 2, 3], timesMs: [0, 10, 20], series: [[0, 1, 1]] }, 4);
    buffer = appendTrend(buffer, { names: ['A'], scans: [4, 5, 6], timesMs: [30, 40, 50], series: [[0, 0, 1]] }, 4);
    expect(buffer.scans).toEqual([3, 4, 5, 6]);
    expect(buffer.series[0]).toEqual([1, 0, 0, 1]);
  });

  test('a restart (scan numbers going back) starts a fresh window instead of drawing back in time', () => {
    let buffer = appendTrend(emptyTrend(['A']), { names: ['A'], scans: [7, 8], timesMs: [60, 70], series: [[1, 1]] }, 10);
    buffer = appendTrend(buffer, { names: ['A'], scans: [1, 2], timesMs: [0, 10], series: [[0, 0]] }, 10);
    expect(buffer.scans).toEqual([1, 2]);
  });
});

describe('program layout', () => {
  test('power bytes of every network are packed in document order, found by element id', () => {
    const project = threeNetworks();
    const layout = buildLayout(project, 'Main', ['Start', 'Stop', 'Motor', 'Lamp', 'Horn'], 10);
    const networks = project.pous[0]!.networks;
    expect(layout.elementOffsets).toEqual([0, 5, 7, 9]);
    expect(layout.vlinkOffsets).toEqual([0, 1, 1, 1]);
    expect(layout.elementIds[5]).toBe(networks[1]!.elements[0]!.id);
    expect(layout.variables.find((v) => v.name === 'Start')).toMatchObject({ type: 'BOOL', role: 'input', location: '%IX0.0' });
    expect(layout.variables.find((v) => v.name === 'Horn')).toMatchObject({ role: 'local' });
  });

  test('FB pins are named Instance.PIN with their pin type', () => {
    const project = timerProgram();
    const names = readableNames(project, project.pous[0]!).map((v) => `${v.name}:${v.type}`);
    expect(names).toEqual(expect.arrayContaining(['T1.IN:BOOL', 'T1.PT:TIME', 'T1.Q:BOOL', 'T1.ET:TIME', 'Enable:BOOL']));
  });

  test('titles and comments do not change what runs; a changed contact does', () => {
    const project = motorProgram();
    const pou = project.pous[0]!;
    const network = pou.networks[0]!;
    const retitled = { ...project, pous: [{ ...pou, networks: [{ ...network, title: 'Seal-in', comment: 'why' }] }] };
    expect(programFingerprint(retitled)).toBe(programFingerprint(project));
    const changed = {
      ...project,
      pous: [{ ...pou, networks: [{ ...network, elements: network.elements.map((e) => (e.kind === 'contact' && e.variable === 'Stop' ? { ...e, contact: 'NO' as const } : e)) }] }],
    };
    expect(programFingerprint(changed)).not.toBe(programFingerprint(project));
  });
});
