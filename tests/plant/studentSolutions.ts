// A student's solution to a machine's exercise, written in ST for brevity (the scenario judges
// behaviour, not the language): the exercise's project with its Main POU replaced, the machine's
// I/O declared as "Declare the machine's I/O" does, plus the solution's own variables. Run as CI
// runs it (`rungsmith test`), the first FAIL line is what the student reads.
import { newPou, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { plantVariables } from '../../src/plant/exerciseKit';
import { requirePlant } from '../../src/plant/machines';
import { rungsmith } from '../cli/memoryIo';

/** `own`: "Name: TYPE" entries of the solution's own variables. */
export function studentSolution(exercise: Project, source: string, own: string[] = []): Project {
  const model = requirePlant(exercise.plant!.id);
  const main = newPou('Main', {
    variables: [
      ...plantVariables(model),
      ...own.map((v) => {
        const [name, type] = v.split(':').map((t) => t.trim());
        return variable(name!, type!);
      }),
    ],
    networks: [],
    language: 'ST',
    source,
  });
  return { ...exercise, pous: [main] };
}

/** `rungsmith test` on the project: the exit code and the report's first line (PASS or FAIL …). */
export function testRun(project: Project): { code: number; first: string; out: string } {
  const r = rungsmith(['test', 'p.json'], { 'p.json': JSON.stringify(project) });
  return { code: r.code, first: r.out.split('\n')[0] ?? '', out: r.out };
}
