// `rungsmith simulate` of a project whose only program runs in an event task: it runs as the
// configuration (only when the trigger rises), not every scan as a lone program would.
import { expect, it } from 'vitest';
import { saveProject } from '../../src/model/load';
import { eventProject } from '../engine/eventTasksProject';
import { rungsmith } from './memoryIo';

it('an event task with one program runs it on the trigger\'s rise only (TRUE from the start: the first scan)', () => {
  const files = { 'events.json': saveProject(eventProject({ noCyclic: true, eventMs: 10, pulseInitial: true })) };
  const r = rungsmith(['simulate', 'events.json', '--scans', '3', '--watch', 'StartPulse,V.N'], files);
  expect(r.code).toBe(0);
  expect(r.err).toBe('one scan = one tick of 10 ms: E runs when StartPulse rises\n');
  expect(r.out).toBe('scan,time_ms,StartPulse,V.N\n1,0,1,1\n2,10,1,1\n3,20,1,1\n');
});
