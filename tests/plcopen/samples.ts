// Projects covering every element kind Rungsmith exports (with hand-drawn grids).
import { box, bool, coil, contact, jump, link, links, net, pou, project, ret, vlink } from './build';
import { variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';

/** Every contact and coil type, the inverting contact, retentive coils, series/parallel, fan-out. */
export function allElements(): Project {
  return project([
    pou(
      'Main',
      [
        bool('A', '%IX0.0', { comment: 'first input' }),
        bool('B', '%IX0.1'),
        bool('C', '%IX0.2'),
        bool('Q1', '%QX0.0'),
        bool('Q2', '%QX0.1'),
        bool('Q3'),
        bool('Q4'),
        bool('Q5', undefined, { retain: true }),
        bool('Q6'),
        bool('Q7'),
        bool('Latch'),
        bool('Mem'),
        variable('Limit', 'INT', { constant: true, initial: '7' }),
      ],
      [
        net(
          3,
          6,
          [
            contact(0, 0, 'A'),
            contact(0, 1, 'B', 'NC'),
            contact(0, 2, 'C', 'P'),
            links(0, 3, 5)[0]!,
            link(0, 4),
            coil(0, 5, 'Q1'),
            contact(1, 0, 'B', 'N'),
            link(1, 1),
            link(1, 2),
            contact(2, 0, '', 'NOT'),
            contact(2, 1, 'C'),
            ...links(2, 2, 5),
            coil(2, 5, 'Q2', 'NEG'),
          ],
          [vlink(0, 3)],
          { title: 'Series, parallel and edges', comment: 'A AND NOT B AND rising C, OR falling B' },
        ),
        net(
          4,
          6,
          [
            contact(0, 0, 'A'),
            ...links(0, 1, 4),
            coil(0, 4, 'Latch', 'SET'),
            coil(0, 5, 'Q3'),
            coil(1, 4, 'Latch', 'RESET'),
            coil(2, 4, 'Q4', 'P'),
            coil(3, 4, 'Q5', 'N'),
          ],
          [vlink(0, 4), vlink(1, 4), vlink(2, 4)],
        ),
        net(2, 4, [
          contact(0, 0, 'B'),
          link(0, 1),
          link(0, 2),
          coil(0, 3, 'Mem', 'M'),
          contact(1, 0, 'C'),
          link(1, 1),
          link(1, 2),
          coil(1, 3, 'Q6', 'SM'),
        ]),
        net(1, 4, [contact(0, 0, 'Mem'), link(0, 1), link(0, 2), coil(0, 3, 'Q7', 'RM')]),
      ],
    ),
  ]);
}

/** Timers, counters and functions, including a data wire from ADD.OUT to MOVE.IN. */
export function blocks(): Project {
  return project([
    pou(
      'Main',
      [
        bool('Run', '%IX0.0'),
        bool('Count', '%IX0.1'),
        bool('Clear', '%IX0.2'),
        bool('Lamp', '%QX0.0'),
        bool('Full', '%QX0.1'),
        variable('T1', 'TON'),
        variable('C1', 'CTU'),
        variable('Total', 'INT'),
        variable('Shown', 'INT', { initial: '5' }),
        variable('Elapsed', 'TIME'),
        bool('Moved'),
      ],
      [
        net(2, 7, [
          contact(0, 0, 'Run'),
          box(0, 1, 'TON', { PT: 'T#300ms' }, { ET: 'Elapsed' }, 'T1'),
          ...links(0, 3, 6),
          coil(0, 6, 'Lamp'),
        ]),
        net(3, 7, [
          contact(0, 0, 'Count'),
          box(0, 1, 'CTU', { R: 'Clear', PV: '3' }, { CV: 'Total' }, 'C1'),
          ...links(0, 3, 6),
          coil(0, 6, 'Full'),
        ]),
        net(3, 8, [
          contact(0, 0, 'Run'),
          box(0, 1, 'ADD', { IN1: 'Total', IN2: '10' }),
          link(0, 3),
          link(1, 3),
          box(0, 4, 'MOVE', {}, { OUT: 'Shown' }),
          link(0, 6),
          coil(0, 7, 'Moved'),
        ]),
      ],
    ),
  ]);
}

/** A jump over a network to a label, and a conditional return. */
export function jumps(): Project {
  return project([
    pou(
      'Main',
      [
        bool('Skip', '%IX0.0'),
        bool('Stop', '%IX0.1'),
        bool('X', '%IX0.2'),
        bool('Y1'),
        bool('Y2'),
        bool('Y3'),
      ],
      [
        net(1, 4, [contact(0, 0, 'Skip'), link(0, 1), link(0, 2), jump(0, 3, 'L1')]),
        net(1, 4, [contact(0, 0, 'X'), link(0, 1), link(0, 2), coil(0, 3, 'Y1')]),
        net(1, 4, [contact(0, 0, 'X'), link(0, 1), link(0, 2), coil(0, 3, 'Y2')], [], { label: 'L1' }),
        net(1, 4, [contact(0, 0, 'Stop'), link(0, 1), link(0, 2), ret(0, 3)]),
        net(1, 4, [contact(0, 0, 'X'), link(0, 1), link(0, 2), coil(0, 3, 'Y3')]),
      ],
    ),
  ]);
}
