import { test, expect } from 'vitest';
import { ladder, vars, project, plcOf } from './ladder';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
test('smoke', () => {
  const p = project(vars('Start BOOL %IX0.0', 'Stop BOOL %IX0.1', 'Motor BOOL %QX0.0'), [
    ladder(['[Start] + [/Stop] (Motor)', '[Motor] + . .']),
  ]);
  console.log(checkProject(p).map(formatDiagnostic));
  const plc = plcOf(p);
  plc.scan();
  expect(plc.read('Motor')).toBe(false);
  plc.write('Start', true);
  plc.scan();
  expect(plc.read('Motor')).toBe(true);
  plc.write('Start', false);
  plc.scan();
  expect(plc.read('Motor')).toBe(true);
  plc.write('Stop', true);
  plc.scan();
  expect(plc.read('Motor')).toBe(false);
  console.log(JSON.stringify(plc.snapshot().networks[0]), plc.outputs());
});
