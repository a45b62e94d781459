// Projects with a user FB for the monitoring tests: Motor (Start, Stop -> Run, seal-in) called twice from Main.
import type { Project } from '../../src/model/project';
import { ladder, vars, type BoxSpec } from '../engine/ladder';
import { io, multiProject, pou } from '../engine/userBlocksHelpers';

const motorBox = (instance: string, stop: string): BoxSpec => ({ row: 0, col: 1, type: 'Motor', instance, inputs: { Stop: stop } });

/** FB Motor: network 1 seal-in `Start OR Run, NOT Stop -> Run`, network 2 `Run -> Lamp` (a local). */
export function motorFb() {
  return pou('Motor', 'FUNCTION_BLOCK', [...io('input', 'Start BOOL', 'Stop BOOL'), ...io('output', 'Run BOOL'), ...vars('Lamp BOOL')], [
    ladder(['+ [Start] + [/Stop] (Run)', '+ [Run] + . .']),
    ladder(['[Run] (Lamp)']),
  ]);
}

/** Main: network 1 calls Motor1 (Start1, Stop1), network 2 calls Motor2 (Start2, Stop2), network 3 copies Motor1.Run to Out. */
export function mainProgram(name = 'Main') {
  return pou(name, 'PROGRAM', vars('Start1 BOOL %IX0.0', 'Stop1 BOOL %IX0.1', 'Start2 BOOL %IX0.2', 'Stop2 BOOL %IX0.3', 'Out BOOL %QX0.0', 'Motor1 Motor', 'Motor2 Motor'), [
    ladder(['[Start1] # # .', '. # # .'], { boxes: [motorBox('Motor1', 'Stop1')] }),
    ladder(['[Start2] # # .', '. # # .'], { boxes: [motorBox('Motor2', 'Stop2')] }),
    ladder(['[Motor1.Run] (Out)']),
  ]);
}

export function motorProject(): Project {
  return multiProject([mainProgram(), motorFb()]);
}

/** The project with its task running two instances of Main: a configuration. */
export function configurationProject(): Project {
  const p = motorProject();
  return { ...p, tasks: [{ ...p.tasks[0]!, programs: [{ instance: 'Line1', pou: 'Main' }, { instance: 'Line2', pou: 'Main' }] }] };
}
