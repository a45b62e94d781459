// Binds the real engine to the session's SimEngine interface.
import { compileProgram, createPlc } from '../engine/plc';
import { parseValueText } from '../engine/values/literals';
import { isElementaryType } from '../model/iecTypes';
import { runOptions } from './runTarget';
import type { SimEngine } from './simEngine';

export const realEngine: SimEngine = {
  compile(project) {
    // What the project's tasks run (a configuration when they list several program instances).
    return compileProgram(project, runOptions(project));
  },
  createPlc(program, options) {
    return createPlc(program as Parameters<typeof createPlc>[0], options);
  },
  parseValue(type, text) {
    if (!isElementaryType(type)) return { ok: false, message: `values of type ${type} cannot be typed in` };
    return parseValueText(type, text);
  },
};
