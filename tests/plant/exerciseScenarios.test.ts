// The machines' exercises judged as an instructor would: the mistakes students typically make
// fail the exercise's scenario, each with a message that names the scan, the time or the check
// and what went wrong; a solution that does what the task text asks passes.
import { describe, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { liftReference, tankReference } from '../../src/plant/exercises';
import { boxesReference } from '../../src/plant/boxesExercise';
import { garageReference } from '../../src/plant/garageExercise';
import { intersectionReference } from '../../src/plant/intersectionExercise';
import { mixerReference } from '../../src/plant/mixerExercise';
import { studentSolution, testRun } from './studentSolutions';

describe('tank: the scenario catches the typical mistakes', () => {
  const TANK_OWN = ['Running: BOOL', 'Filling: BOOL'];
  const tankSt = (running: string, fill: string, outputs: string) =>
    studentSolution(tankReference(), `${running}\nRunLamp := Running;\n${fill}\n${outputs}\n`, TANK_OWN);
  const RUNNING = 'Running := (Start OR Running) AND NOT Stop;';
  const LATCH =
    'IF Running AND NOT LowLevel THEN Filling := TRUE; END_IF;\nIF HighLevel OR NOT Running THEN Filling := FALSE; END_IF;';
  const OUTPUTS = 'Pump := Filling; InletValve := Filling; DrainValve := Running AND LowLevel;';

  test('the task written in ST as the text says passes', () => {
    expect(testRun(tankSt(RUNNING, LATCH, OUTPUTS)).first).toBe(
      'PASS Tank held between the switches for 5 minutes (3000 scans)',
    );
  });

  test("the scenario judges the machine's I/O only: a solution with its own names (no Running, no Filling) passes", () => {
    const own = studentSolution(
      tankReference(),
      `On := (Start OR On) AND NOT Stop;
RunLamp := On;
IF On AND Level < 200 THEN Fill := TRUE; END_IF;
IF Level >= 800 OR NOT On THEN Fill := FALSE; END_IF;
Pump := Fill; InletValve := Fill; DrainValve := On AND LowLevel;
`,
      ['On: BOOL', 'Fill: BOOL'],
    );
    expect(own.pous[0]!.variables.map((v) => v.name)).not.toContain('Running');
    expect(testRun(own).first).toBe('PASS Tank held between the switches for 5 minutes (3000 scans)');
  });

  test.each([
    {
      mistake: 'filling only while below the low switch (no latch up to the high switch)',
      st: [RUNNING, 'Filling := Running AND NOT LowLevel;', OUTPUTS],
      fails: 'scan 600 (line 13): tank.level expected 646 ± 50, got 200.95',
    },
    {
      mistake: 'the process drawing from a tank below the low switch',
      st: [RUNNING, LATCH, 'Pump := Filling; InletValve := Filling; DrainValve := Running;'],
      fails: 'scan 20 (line 12): DrainValve expected 0, got 1',
    },
    {
      mistake: 'the drain never opened (the process gets no water)',
      st: [RUNNING, LATCH, 'Pump := Filling; InletValve := Filling; DrainValve := FALSE;'],
      fails: 'scan 600 (line 13): DrainValve expected 1, got 0; tank.level expected 646 ± 50, got 804.25',
    },
    {
      mistake: 'Stop ignored',
      st: ['Running := Start OR Running;', LATCH, OUTPUTS],
      fails:
        'scan 2310 (line 18): RunLamp expected 0, got 1; Pump expected 0, got 1; InletValve expected 0, got 1; DrainValve expected 0, got 1',
    },
    {
      mistake: 'Stop does not end filling',
      st: [
        RUNNING,
        'IF Running AND NOT LowLevel THEN Filling := TRUE; END_IF;\nIF HighLevel THEN Filling := FALSE; END_IF;',
        OUTPUTS,
      ],
      fails: 'scan 2310 (line 18): Pump expected 0, got 1; InletValve expected 0, got 1',
    },
    {
      mistake: 'the pump run without opening the inlet valve',
      st: [RUNNING, LATCH, 'Pump := Filling; InletValve := FALSE; DrainValve := Running AND LowLevel;'],
      fails: 'scan 20 (line 12): InletValve expected 1, got 0',
    },
  ])('$mistake fails: $fails', ({ st, fails }) => {
    const r = testRun(tankSt(st[0]!, st[1]!, st[2]!));
    expect(r.code).toBe(1);
    expect(r.first).toBe(`FAIL Tank held between the switches for 5 minutes: ${fails}`);
  });
});

describe('garage: the scenario catches the typical mistakes', () => {
  const OWN = ['Opening: BOOL', 'Closing: BOOL', 'PreWarn: TON'];
  const OPEN = 'Opening := (KeyOpen OR Opening OR (Closing AND Obstacle)) AND NOT OpenLimit AND NOT Stop;';
  const CLOSE =
    'Closing := (KeyClose OR Closing) AND NOT ClosedLimit AND NOT Stop AND NOT Obstacle AND NOT Opening;';
  const MOTOR = `WarningLamp := Opening OR Closing;
PreWarn(IN := WarningLamp, PT := T#1s);
MotorUp := Opening AND PreWarn.Q AND NOT MotorDown;
MotorDown := Closing AND PreWarn.Q AND NOT MotorUp;`;
  const garageSt = (...lines: string[]) => studentSolution(garageReference(), lines.join('\n'), OWN);
  const NAME = 'Garage door: three cycles on the key, reversing for a car';

  test('the task written in ST as the text says passes', () => {
    expect(testRun(garageSt(OPEN, CLOSE, MOTOR)).first).toBe(`PASS ${NAME} (1200 scans)`);
  });

  test('a correct design slower than the reference passes: a 2 s pre-warning', () => {
    expect(testRun(garageSt(OPEN, CLOSE, MOTOR.replace('T#1s', 'T#2s'))).first).toBe(
      `PASS ${NAME} (1200 scans)`,
    );
  });

  test.each([
    {
      mistake: 'Stop ignored',
      st: [
        'Opening := (KeyOpen OR Opening OR (Closing AND Obstacle)) AND NOT OpenLimit;',
        'Closing := (KeyClose OR Closing) AND NOT ClosedLimit AND NOT Obstacle AND NOT Opening;',
        MOTOR,
      ],
      fails: 'scan 1080 (line 38): MotorUp expected 0, got 1; garage.moving expected 0, got 1',
    },
    {
      mistake: 'KeyClose not locked out while the door opens (no interlock of the directions)',
      st: [
        OPEN,
        'Closing := (KeyClose OR Closing) AND NOT ClosedLimit AND NOT Stop AND NOT Obstacle;',
        'WarningLamp := Opening OR Closing; PreWarn(IN := WarningLamp, PT := T#1s);',
        'MotorUp := Opening AND PreWarn.Q; MotorDown := Closing AND PreWarn.Q;',
      ],
      fails: 'MotorUp and MotorDown were on together (short circuit) at scan 760 (75.90 s)',
    },
    {
      mistake: 'the closing door only stops for the car (no reversing)',
      st: ['Opening := (KeyOpen OR Opening) AND NOT OpenLimit AND NOT Stop;', CLOSE, MOTOR],
      fails:
        'scan 540 (line 21): OpenLimit expected 1, got 0; garage.position expected 99.5 ± 1, got 83.333336',
    },
    {
      mistake: 'the pre-warning timer too short',
      st: [
        OPEN,
        CLOSE,
        'WarningLamp := Opening OR Closing; PreWarn(IN := WarningLamp, PT := T#500ms);',
        'MotorUp := Opening AND PreWarn.Q AND NOT MotorDown; MotorDown := Closing AND PreWarn.Q AND NOT MotorUp;',
      ],
      fails: 'scan 150 (line 12): garage.unwarned expected 0, got 1',
    },
  ])('$mistake fails: $fails', ({ st, fails }) => {
    const r = testRun(garageSt(...st));
    expect(r.code).toBe(1);
    expect(r.first).toBe(`FAIL ${NAME}: ${fails}`);
  });

  test('a pre-warning too short also says, located, what the warning was', () => {
    const r = testRun(
      garageSt(
        OPEN,
        CLOSE,
        'WarningLamp := Opening OR Closing; PreWarn(IN := WarningLamp, PT := T#500ms);',
        'MotorUp := Opening AND PreWarn.Q AND NOT MotorDown; MotorDown := Closing AND PreWarn.Q AND NOT MotorUp;',
      ),
    );
    expect(r.out).toContain(
      'warning: the door started to move less than 1 s after the warning lamp lit at scan 6 (0.50 s)',
    );
  });
});

describe('boxes: the scenario catches the typical mistakes', () => {
  const OWN = ['Running: BOOL', 'Large: BOOL', 'Pushing: BOOL', 'T1: TON'];
  const RUN = 'Running := (Start OR Running) AND NOT Stop; Conveyor := Running; RunLamp := Running;';
  const SORT = `IF SizeEye THEN Large := TRUE; END_IF;
IF PusherEye AND Large THEN Pushing := TRUE; END_IF;
IF PusherOut THEN Pushing := FALSE; Large := FALSE; END_IF;
Pusher := Pushing;`;
  const boxesSt = (...lines: string[]) => studentSolution(boxesReference(), lines.join('\n'), OWN);
  const NAME = 'Ten boxes sorted by size';

  test('the task written in ST as the text says passes', () => {
    expect(testRun(boxesSt(RUN, SORT)).first).toBe(`PASS ${NAME} (570 scans)`);
  });

  test('a correct design slower than the reference passes: the belt stopped while the pusher pushes', () => {
    const stopping = RUN.replace('Conveyor := Running;', 'Conveyor := Running AND NOT Pushing;');
    expect(stopping).not.toBe(RUN);
    expect(testRun(boxesSt(stopping, SORT)).first).toBe(`PASS ${NAME} (570 scans)`);
  });

  test.each([
    {
      mistake: 'Stop ignored',
      st: ['Running := Start OR Running; Conveyor := Running; RunLamp := Running;', SORT],
      fails:
        'scan 275 (line 14): Conveyor expected 0, got 1; RunLamp expected 0, got 1; boxes.speed expected 0, got 100',
    },
    {
      mistake: 'the run lamp forgotten',
      st: ['Running := (Start OR Running) AND NOT Stop; Conveyor := Running;', SORT],
      fails: 'scan 3 (line 10): RunLamp expected 1, got 0',
    },
    {
      mistake: 'the push timed from the size sensor (3 s at belt speed) instead of the eye at the pusher',
      st: [
        RUN,
        `IF SizeEye THEN Large := TRUE; END_IF;
T1(IN := Large, PT := T#3s);
IF T1.Q AND Large THEN Pushing := TRUE; END_IF;
IF PusherOut THEN Pushing := FALSE; Large := FALSE; END_IF;
Pusher := Pushing;`,
      ],
      fails: 'box 6 (large) ran into the small-box bin at scan 352 (35.10 s)',
    },
    {
      mistake: 'the large box never forgotten',
      st: [
        RUN,
        `IF SizeEye THEN Large := TRUE; END_IF;
IF PusherEye AND Large THEN Pushing := TRUE; END_IF;
IF PusherOut THEN Pushing := FALSE; END_IF;
Pusher := Pushing;`,
      ],
      fails: 'box 4 (small) was pushed into the large-box chute at scan 196 (19.50 s)',
    },
    {
      mistake: 'the pusher held out for a fixed 0.3 s instead of to its out limit',
      st: [
        RUN,
        `IF SizeEye THEN Large := TRUE; END_IF;
IF PusherEye AND Large THEN Pushing := TRUE; END_IF;
T1(IN := Pushing, PT := T#300ms);
IF T1.Q THEN Pushing := FALSE; Large := FALSE; END_IF;
Pusher := Pushing;`,
      ],
      fails: 'box 2 (large) fell off the belt (pushed 45 % across, then let go) at scan 104 (10.30 s)',
    },
  ])('$mistake fails: $fails', ({ st, fails }) => {
    const r = testRun(boxesSt(...st));
    expect(r.code).toBe(1);
    expect(r.first).toBe(`FAIL ${NAME}: ${fails}`);
  });
});

describe('mixer: the scenario catches the typical mistakes', () => {
  const OWN = [
    'Running: BOOL',
    'DoseA: BOOL',
    'DoseB: BOOL',
    'Mixing: BOOL',
    'Emptying: BOOL',
    'AtTemp: BOOL',
    'Holding: BOOL',
    'HoldTime: TON',
    'EmptyTime: TON',
  ];
  const RUN = 'Running := (Start OR Running) AND NOT Stop;';
  const DOSE = `IF Running AND NOT LowLevel AND NOT DoseA AND NOT DoseB AND NOT Mixing AND NOT Emptying THEN DoseA := TRUE; END_IF;
IF DoseA AND MidLevel THEN DoseB := TRUE; DoseA := FALSE; END_IF;
IF DoseB AND HighLevel THEN Mixing := TRUE; DoseB := FALSE; END_IF;`;
  const HOLD = `AtTemp := Mixing AND Temperature >= 600;
IF Mixing AND AtTemp THEN Holding := TRUE; END_IF;
HoldTime(IN := Holding AND Running, PT := T#30s);`;
  const EMPTY = `IF HoldTime.Q THEN Emptying := TRUE; Mixing := FALSE; Holding := FALSE; END_IF;
EmptyTime(IN := Emptying AND Running AND NOT LowLevel, PT := T#4s);
IF EmptyTime.Q THEN Emptying := FALSE; END_IF;`;
  const OUT = `ValveA := DoseA AND Running; ValveB := DoseB AND Running; Agitator := Mixing AND Running;
Heater := Mixing AND Running AND AgitatorOn AND LowLevel AND NOT AtTemp AND NOT HoldTime.Q;
OutletValve := Emptying AND Running; DoneLamp := Emptying;`;
  const mixerSt = (...lines: string[]) => studentSolution(mixerReference(), lines.join('\n'), OWN);
  const NAME = 'Three good batches';

  test('the task written in ST as the text says passes', () => {
    expect(testRun(mixerSt(RUN, DOSE, HOLD, EMPTY, OUT)).first).toBe(`PASS ${NAME} (3600 scans)`);
  });

  test('a correct design slower than the reference passes: a 35 s hold, the outlet open 6 s after the low switch', () => {
    const slow = mixerSt(RUN, DOSE, HOLD.replace('T#30s', 'T#35s'), EMPTY.replace('T#4s', 'T#6s'), OUT);
    expect(testRun(slow).first).toBe(`PASS ${NAME} (3600 scans)`);
  });

  test.each([
    {
      mistake: 'Stop ignored',
      st: ['Running := Start OR Running;', DOSE, HOLD, EMPTY, OUT],
      fails: 'scan 2610 (line 20): Agitator expected 0, got 1; Heater expected 0, got 1',
    },
    {
      mistake: 'the done lamp forgotten',
      st: [RUN, DOSE, HOLD, EMPTY, OUT.replace(' DoneLamp := Emptying;', '')],
      fails: 'scan 1000 (line 15): DoneLamp expected 1, got 0',
    },
    {
      mistake: 'A and B dosed together up to the high switch',
      st: [
        RUN,
        `IF Running AND NOT LowLevel AND NOT DoseA AND NOT DoseB AND NOT Mixing AND NOT Emptying THEN DoseA := TRUE; DoseB := TRUE; END_IF;
IF DoseA AND HighLevel THEN Mixing := TRUE; DoseA := FALSE; DoseB := FALSE; END_IF;`,
        HOLD,
        EMPTY,
        OUT,
      ],
      fails: 'scan 50 (line 12): ValveB expected 0, got 1',
    },
    {
      mistake: 'the outlet closed as soon as the low switch goes OFF',
      st: [
        RUN,
        DOSE,
        HOLD,
        'IF HoldTime.Q THEN Emptying := TRUE; Mixing := FALSE; Holding := FALSE; END_IF;\nIF Emptying AND NOT LowLevel THEN Emptying := FALSE; END_IF;',
        OUT,
      ],
      fails:
        'the vessel was not emptied (the outlet closed with 94.1 L left): the next batch was dosed onto it, and the last batch is not counted at scan 1,053 (105.20 s)',
    },
    {
      mistake: 'the heater switched off for good at 60 °C (no thermostat through the hold)',
      st: [RUN, DOSE, HOLD, EMPTY, OUT.replace('AND NOT AtTemp AND NOT HoldTime.Q', 'AND NOT Holding')],
      fails:
        'a batch was discharged held only 21.4 s at 57 °C or above with the agitator running (it must be held 30 s at 60 °C) and is spoiled at scan 903 (90.20 s)',
    },
  ])('$mistake fails: $fails', ({ st, fails }) => {
    const r = testRun(mixerSt(...st));
    expect(r.code).toBe(1);
    expect(r.first).toBe(`FAIL ${NAME}: ${fails}`);
  });
});

describe('lift: the scenario catches the typical mistakes', () => {
  const OWN = [
    'Req1: BOOL',
    'Req2: BOOL',
    'Req3: BOOL',
    'Here: BOOL',
    'Above: BOOL',
    'Below: BOOL',
    'Standstill: TON',
    'Dwell: TON',
  ];
  const CALLS = `IF Call1 THEN Req1 := TRUE; END_IF; IF Call2 THEN Req2 := TRUE; END_IF; IF Call3 THEN Req3 := TRUE; END_IF;
IF AtFloor1 AND DoorOpened THEN Req1 := FALSE; END_IF;
IF AtFloor2 AND DoorOpened THEN Req2 := FALSE; END_IF;
IF AtFloor3 AND DoorOpened THEN Req3 := FALSE; END_IF;
CallLamp1 := Req1; CallLamp2 := Req2; CallLamp3 := Req3;
Here := (AtFloor1 AND Req1) OR (AtFloor2 AND Req2) OR (AtFloor3 AND Req3);
Above := (AtFloor1 AND (Req2 OR Req3)) OR (AtFloor2 AND Req3);
Below := (AtFloor3 AND (Req2 OR Req1)) OR (AtFloor2 AND Req1);
Standstill(IN := NOT MotorUp AND NOT MotorDown, PT := T#300ms);
IF Here AND Standstill.Q THEN DoorOpen := TRUE; END_IF;`;
  const DWELL = `Dwell(IN := DoorOpen AND DoorOpened, PT := T#2s);
IF Dwell.Q THEN DoorOpen := FALSE; END_IF;`;
  const GO = `IF Above AND NOT Here AND DoorClosed AND NOT DoorOpen AND NOT MotorDown THEN MotorUp := TRUE; END_IF;
IF Below AND NOT Here AND DoorClosed AND NOT DoorOpen AND NOT MotorUp THEN MotorDown := TRUE; END_IF;`;
  const STOP = `IF (AtFloor2 AND Req2) OR AtFloor3 THEN MotorUp := FALSE; END_IF;
IF (AtFloor2 AND Req2) OR AtFloor1 THEN MotorDown := FALSE; END_IF;`;
  const liftSt = (...lines: string[]) => studentSolution(liftReference(), lines.join('\n'), OWN);
  const NAME = 'Six calls answered, level with the floors';

  test('the task written in ST as the text says passes', () => {
    expect(testRun(liftSt(CALLS, DWELL, GO, STOP)).first).toBe(`PASS ${NAME} (5000 scans)`);
  });

  test.each([
    ['waits 0.5 s at rest before opening the door', 'T#300ms', 'T#500ms'],
    ['waits 0.15 s at rest before opening the door', 'T#300ms', 'T#150ms'],
  ])('a correct design other than the reference passes: it %s', (_what, from, to) => {
    expect(testRun(liftSt(CALLS.replace(from, to), DWELL, GO, STOP)).first).toBe(`PASS ${NAME} (5000 scans)`);
  });

  test.each([
    {
      mistake: 'the door closed as soon as it is fully open (no 2 s dwell)',
      st: [CALLS, 'IF DoorOpened THEN DoorOpen := FALSE; END_IF;', GO, STOP],
      fails: 'scan 500 (line 11): DoorOpened expected 1, got 0',
    },
    {
      mistake: 'no stop at a called floor the car passes',
      st: [
        CALLS,
        DWELL,
        GO,
        'IF AtFloor3 THEN MotorUp := FALSE; END_IF;\nIF AtFloor1 THEN MotorDown := FALSE; END_IF;',
      ],
      fails:
        'scan 500 (line 11): CallLamp2 expected 0, got 1; lift.served expected 1, got 0; lift.floor expected 2, got 0; DoorOpened expected 1, got 0',
    },
    {
      mistake: 'the call not remembered (the lamp follows the button)',
      st: [
        CALLS.replace(
          'CallLamp1 := Req1; CallLamp2 := Req2; CallLamp3 := Req3;',
          'CallLamp1 := Call1; CallLamp2 := Call2; CallLamp3 := Call3;',
        ),
        DWELL,
        GO,
        STOP,
      ],
      fails: 'scan 6 (line 8): CallLamp3 expected 1, got 0',
    },
  ])('$mistake fails: $fails', ({ st, fails }) => {
    const r = testRun(liftSt(...st));
    expect(r.code).toBe(1);
    expect(r.first).toBe(`FAIL ${NAME}: ${fails}`);
  });
});

describe('intersection: the scenario catches the typical mistakes', () => {
  const OWN = [
    'AskMain: BOOL',
    'AskSide: BOOL',
    'Demand: BOOL',
    'Cycle: BOOL',
    'MainGreenTime: TON',
    'MainYellowTime: TON',
    'AllRedTime1: TON',
    'SideGreenTime: TON',
    'SideYellowTime: TON',
    'AllRedTime2: TON',
    'WalkSideTime: TON',
    'WalkMainTime: TON',
  ];
  const ASK = `IF CrossMain THEN AskMain := TRUE; END_IF; IF WalkMain THEN AskMain := FALSE; END_IF;
IF CrossSide THEN AskSide := TRUE; END_IF; IF WalkSide THEN AskSide := FALSE; END_IF;
Demand := LoopSide OR AskMain OR AskSide;`;
  const times = (yellow: string, allRed: string) => `MainGreenTime(IN := NOT Cycle, PT := T#20s);
IF MainGreenTime.Q AND Demand THEN Cycle := TRUE; END_IF;
MainYellowTime(IN := Cycle, PT := ${yellow});
AllRedTime1(IN := MainYellowTime.Q, PT := ${allRed});
SideGreenTime(IN := AllRedTime1.Q, PT := T#10s);
SideYellowTime(IN := SideGreenTime.Q, PT := ${yellow});
AllRedTime2(IN := SideYellowTime.Q, PT := ${allRed});
IF AllRedTime2.Q THEN Cycle := FALSE; END_IF;
WalkSideTime(IN := NOT Cycle, PT := T#5s);
WalkMainTime(IN := AllRedTime1.Q, PT := T#4s);`;
  const LAMPS = `MainGreen := NOT Cycle; MainYellow := Cycle AND NOT MainYellowTime.Q; MainRed := Cycle AND MainYellowTime.Q;
SideGreen := Cycle AND AllRedTime1.Q AND NOT SideGreenTime.Q;
SideYellow := Cycle AND SideGreenTime.Q AND NOT SideYellowTime.Q;
SideRed := NOT SideGreen AND NOT SideYellow;
WalkMain := Cycle AND AllRedTime1.Q AND NOT WalkMainTime.Q; DontWalkMain := NOT WalkMain;
WalkSide := NOT Cycle AND NOT WalkSideTime.Q; DontWalkSide := NOT WalkSide;`;
  const st = (...lines: string[]) => studentSolution(intersectionReference(), lines.join('\n'), OWN);
  const NAME = 'Side road and pedestrians served for 5 minutes, no conflict';

  test('the task written in ST as the text says passes', () => {
    expect(testRun(st(ASK, times('T#3s', 'T#2s'), LAMPS)).first).toBe(`PASS ${NAME} (3000 scans)`);
  });

  test('a correct design other than the reference passes: a 25 s minimum green, 4 s of yellow, 3 s of all red', () => {
    const other = times('T#4s', 'T#3s').replace(
      'MainGreenTime(IN := NOT Cycle, PT := T#20s);',
      'MainGreenTime(IN := NOT Cycle, PT := T#25s);',
    );
    expect(other).toContain('T#25s');
    expect(testRun(st(ASK, other, LAMPS)).first).toBe(`PASS ${NAME} (3000 scans)`);
  });

  test.each([
    {
      mistake: 'a 1 s yellow',
      st: [ASK, times('T#1s', 'T#2s'), LAMPS],
      fails:
        'the main road went from green to red after 1.0 s of yellow (at least 3 s of yellow asked) at scan 211 (21.00 s)',
    },
    {
      mistake: 'no all-red between the roads',
      st: [ASK, times('T#3s', 'T#0s'), LAMPS],
      fails:
        'the side road got green 0.1 s after the main road turned red (both roads red at least 2 s asked) at scan 232 (23.10 s)',
    },
    {
      mistake: 'WALK over the main road lit the whole side road green (10 s)',
      st: [
        ASK,
        times('T#3s', 'T#2s').replace(
          'WalkMainTime(IN := AllRedTime1.Q, PT := T#4s);',
          'WalkMainTime(IN := AllRedTime1.Q, PT := T#10s);',
        ),
        LAMPS,
      ],
      fails: 'the main road got green while pedestrians were still crossing it at scan 1,604 (160.30 s)',
    },
    {
      mistake: 'WALK over the side road lit the whole main road green',
      st: [
        ASK,
        times('T#3s', 'T#2s'),
        LAMPS.replace('WalkSide := NOT Cycle AND NOT WalkSideTime.Q;', 'WalkSide := NOT Cycle;'),
      ],
      fails: 'the side road got green while pedestrians were still crossing it at scan 1,855 (185.40 s)',
    },
    {
      mistake: 'the side road green straight to red',
      st: [
        ASK,
        times('T#3s', 'T#2s'),
        LAMPS.replace(
          'SideYellow := Cycle AND SideGreenTime.Q AND NOT SideYellowTime.Q;',
          'SideYellow := FALSE;',
        ),
      ],
      fails:
        'the side road went from green to red without yellow (at least 3 s of yellow asked) at scan 351 (35.00 s)',
    },
  ])('$mistake fails: $fails', ({ st: lines, fails }) => {
    const r = testRun(st(...lines));
    expect(r.code).toBe(1);
    expect(r.first).toBe(`FAIL ${NAME}: ${fails}`);
  });
});

describe('every reference solution reaches its goal at every scan cycle it is meant for', () => {
  /** The scenario's operator actions at `cycle` (each at the same PLC time), then the goal checked `afterMs` after its last row. */
  const atCycle = (csv: string, cycle: number, goal: string, value: string, afterMs = 2000): string => {
    const from = Number(/^# cycle: (\d+)ms$/m.exec(csv)![1]);
    const lines = csv
      .trim()
      .split('\n')
      .filter((l) => !l.startsWith('#'));
    const head = lines[0]!.split(',');
    const inputs = head.map((h, i) => (h.startsWith('expect') ? -1 : i)).filter((i) => i > 0);
    let last = 0;
    let lastMs = 0;
    const rows: string[] = [];
    for (const line of lines.slice(1)) {
      const cells = line.split(',');
      const ms = (Number(cells[0]) - 1) * from;
      lastMs = ms;
      const set = inputs.map((i) => cells[i] ?? '');
      if (set.every((c) => c === '')) continue;
      // A press of one scan at the scenario's cycle still lasts one scan here.
      const scan = Math.max(last + 1, Math.round(ms / cycle) + 1);
      last = scan;
      rows.push([scan, ...set, ''].join(','));
    }
    const end = Math.max(last + 1, Math.round((lastMs + afterMs) / cycle) + 1);
    rows.push([end, ...inputs.map(() => ''), value].join(','));
    return `# plant: ${/^# plant: (\w+)$/m.exec(csv)![1]}\n# cycle: ${cycle}ms\nscan,${inputs.map((i) => head[i]).join(',')},expect ${goal}\n${rows.join('\n')}\n`;
  };
  test.each([
    {
      id: 'tank',
      reference: tankReference,
      goal: 'tank.deadheads',
      value: '0',
      cycles: [1, 10, 50, 100, 200],
    },
    {
      id: 'boxes',
      reference: boxesReference,
      goal: 'boxes.sorted',
      value: '10',
      cycles: [1, 10, 50, 100, 200],
      // At the scenario's end: the 11th box comes 0.7 s after it.
      afterMs: 0,
    },
    {
      id: 'garage',
      reference: garageReference,
      goal: 'garage.cycles',
      value: '3',
      cycles: [1, 10, 50, 100, 200],
    },
    {
      id: 'mixer',
      reference: mixerReference,
      goal: 'mixer.batches',
      value: '3',
      cycles: [1, 10, 50, 100, 200],
    },
    {
      id: 'intersection',
      reference: intersectionReference,
      goal: 'intersection.ped_served',
      value: '7',
      cycles: [1, 10, 50, 100, 200],
    },
    // The lift needs a scan of 20 ms or faster (its task text says so): at 50 ms it stops off the floor.
    { id: 'lift', reference: liftReference, goal: 'lift.served', value: '6', cycles: [1, 10, 20] },
  ] as {
    id: string;
    reference: () => Project;
    goal: string;
    value: string;
    cycles: number[];
    afterMs?: number;
  }[])('$id at $cycles ms', ({ reference, goal, value, cycles, afterMs }) => {
    for (const cycle of cycles) {
      const project = reference();
      const csv = atCycle(project.scenarios![0]!.csv, cycle, goal, value, afterMs);
      const r = testRun({ ...project, scenarios: [{ name: `at ${cycle} ms`, csv }] });
      expect([cycle, r.first]).toEqual([cycle, expect.stringMatching(/^PASS at \d+ ms/)]);
    }
  });

  test('the lift at 50 ms stops off the floor, as its task text warns', () => {
    const project = liftReference();
    const csv = atCycle(project.scenarios![0]!.csv, 50, 'lift.misstops', '0');
    expect(testRun({ ...project, scenarios: [{ name: 'at 50 ms', csv }] }).out).toContain(
      'warning: the car stopped 25 mm above floor 2',
    );
  });
});
