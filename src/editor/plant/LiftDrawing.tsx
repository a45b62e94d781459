// The lift, drawn with Konva from a LiftState (src/plant/lift.ts): the shaft with its three
// landings, the car at its level with its door opening, the hoist motor coloured by how it runs,
// the floor sensors lit when ON, the call lamps and the passengers waiting at each landing, and
// the consequences on the drawing (overrun, crash, moving with the door open, a stop off the floor).
import { Circle, Group, Line, Rect, Text } from 'react-konva';
import {
  BUFFER_MM,
  FLOOR_MM,
  FLOOR_WINDOW_MM,
  SPEED_MM_S,
  TOP_MM,
  levelFloor,
  type LiftState,
} from '../../plant/lift';
import type { PlantDrawingProps } from './drawings';

export const LIFT_SIZE = { width: 320, height: 330 } as const;

const LIT = '#22c55e';
const DARK = '#4b5563';
const AMBER = '#eab308';
const LAMP = '#facc15';
const OFF = '#e5e7eb';
const ALARM = '#dc2626';
const INK = '#111827';
const LABEL = '#374151';

/** The car's height in the shaft, mm (drawn above its floor level). */
const CAR_MM = 2400;
/** mm above floor 1 -> y: the pit (-400 mm) at y 292, 0.03 px a mm. */
const K = 0.03;
const yOf = (mm: number) => 292 - (mm + 400) * K;
/** The shaft: x 110..190, from the headroom to the pit. */
const S = { x: 110, w: 80, top: 14, bottom: 292 } as const;
const CAR = { x: S.x + 8, w: S.w - 16 } as const;

function Spring({ x, y1, y2, hit }: { x: number; y1: number; y2: number; hit: boolean }) {
  const n = 4;
  const points: number[] = [];
  for (let i = 0; i <= n * 2; i++) points.push(x + (i % 2 ? 6 : -6), y1 + ((y2 - y1) * i) / (n * 2));
  return <Line points={points} stroke={hit ? ALARM : DARK} strokeWidth={hit ? 3 : 2} />;
}

function Landing({ s, i, sensed }: { s: LiftState; i: number; sensed: PlantDrawingProps['sensed'] }) {
  const y = yOf(FLOOR_MM[i]!);
  const lamp = i === 0 ? s.lamp1 : i === 1 ? s.lamp2 : s.lamp3;
  const call = i === 0 ? s.call1 : i === 1 ? s.call2 : s.call3;
  // Lit as the program reads it, faults applied (a sensor stuck OFF stays dark with the car level).
  const at = sensed ? sensed[`AtFloor${i + 1}`] === true : Math.abs(s.position - FLOOR_MM[i]!) <= FLOOR_WINDOW_MM;
  return (
    <Group>
      {/* The landing floor and its number. */}
      <Line points={[16, y, S.x, y]} stroke={INK} strokeWidth={3} />
      <Text text={`Floor ${i + 1}`} x={16} y={y + 4} fontSize={11} fill={LABEL} />
      {/* Call lamp beside the landing door. */}
      <Circle x={96} y={y - 36} radius={7} fill={lamp ? LAMP : OFF} stroke={INK} strokeWidth={1} />
      <Text text="Call" x={80} y={y - 26} width={32} align="center" fontSize={9} fill={LABEL} />
      {/* A passenger waiting for the car, and for how long. */}
      {call >= 0 && (
        <Group x={34} y={y - 30}>
          <Circle y={-14} radius={5} fill="#2563eb" />
          <Line points={[0, -9, 0, 8, -5, 28, 0, 8, 5, 28]} stroke="#2563eb" strokeWidth={3} />
          <Text
            text={`${((s.timeMs - call) / 1000).toFixed(0)} s`}
            x={-26}
            y={-30}
            width={28}
            align="right"
            fontSize={10}
            fill={LABEL}
          />
        </Group>
      )}
      {/* Floor sensor on the shaft wall, lit when ON. */}
      <Line points={[S.x + S.w, y, S.x + S.w + 10, y]} stroke={DARK} strokeWidth={2} />
      <Circle x={S.x + S.w + 16} y={y} radius={6} fill={at ? LIT : OFF} stroke={INK} strokeWidth={1} />
      <Text text={`AtFloor${i + 1}`} x={S.x + S.w + 25} y={y - 6} fontSize={10} fill={INK} />
    </Group>
  );
}

export function LiftDrawing({ state, sensed }: PlantDrawingProps) {
  const s = state as LiftState;
  const carBottom = yOf(s.position);
  const carTop = yOf(s.position + CAR_MM);
  const carH = carBottom - carTop;
  const running = Math.abs(s.speed);
  const motor = running >= SPEED_MM_S ? LIT : running > 0 ? AMBER : DARK;
  const half = CAR.w / 2;
  const panel = half * (1 - s.door);
  const level = levelFloor(s.position);
  const offFloor = s.speed === 0 && Math.abs(s.stopOffset) > FLOOR_WINDOW_MM && !s.crashed;
  return (
    <Group>
      {/* Shaft, pit buffer and headroom buffer. */}
      <Rect
        x={S.x}
        y={S.top}
        width={S.w}
        height={S.bottom - S.top}
        fill="#f3f4f6"
        stroke={INK}
        strokeWidth={2}
      />
      <Spring x={S.x + S.w / 2} y1={yOf(-BUFFER_MM)} y2={S.bottom} hit={s.crashed && s.position < 0} />
      <Spring
        x={S.x + S.w / 2}
        y1={S.top}
        y2={yOf(TOP_MM + BUFFER_MM + CAR_MM)}
        hit={s.crashed && s.position > 0}
      />
      {[0, 1, 2].map((i) => (
        <Landing key={i} s={s} i={i} sensed={sensed} />
      ))}
      {/* Hoist motor: off, ramping or braking, at full speed; the rope to the car. */}
      <Line points={[S.x + S.w / 2, S.top + 2, S.x + S.w / 2, carTop]} stroke={DARK} strokeWidth={1} />
      <Group x={262} y={34}>
        <Circle radius={16} fill={s.bothOn ? ALARM : motor} stroke={INK} strokeWidth={1} />
        {s.motorUp && !s.motorDown && <Line points={[-7, 5, 0, -7, 7, 5]} closed fill="#f9fafb" />}
        {s.motorDown && !s.motorUp && <Line points={[-7, -5, 0, 7, 7, -5]} closed fill="#f9fafb" />}
        <Text text="Motor" x={-24} y={19} width={48} align="center" fontSize={10} fill={LABEL} />
        <Text
          text={`${Math.round(s.speed)} mm/s`}
          x={-40}
          y={31}
          width={80}
          align="center"
          fontSize={10}
          fill={LABEL}
        />
      </Group>
      <Line points={[S.x + S.w / 2, S.top + 2, 246, 34]} stroke={DARK} strokeWidth={1} />
      {/* The car, its door panels sliding open (the light inside shows through). */}
      <Group x={CAR.x} y={carTop}>
        <Rect width={CAR.w} height={carH} fill="#fef9c3" stroke={INK} strokeWidth={2} />
        <Rect x={1} y={14} width={panel} height={carH - 15} fill={s.doorMoving ? ALARM : '#9ca3af'} />
        <Rect
          x={CAR.w - 1 - panel}
          y={14}
          width={panel}
          height={carH - 15}
          fill={s.doorMoving ? ALARM : '#9ca3af'}
        />
        <Text
          text={`${Math.round(s.position).toLocaleString('en-US')} mm`}
          y={2}
          width={CAR.w}
          align="center"
          fontSize={10}
          fontStyle="bold"
          fill={INK}
        />
      </Group>
      <Text
        text={s.door <= 0 ? 'Door closed' : s.door >= 1 ? 'Door open' : `Door ${Math.round(s.door * 100)} %`}
        x={206}
        y={118}
        fontSize={11}
        fill={s.doorCmd ? '#15803d' : LABEL}
      />
      <Text
        text={level ? `Level with floor ${level}` : s.speed !== 0 ? 'Travelling' : 'Between floors'}
        x={206}
        y={132}
        fontSize={11}
        fill={LABEL}
      />
      <Text text={`Served ${s.served}`} x={206} y={146} fontSize={11} fill={LABEL} />
      {/* Consequences on the drawing. */}
      {s.doorMoving && (
        <Text
          text="MOVING, DOOR OPEN"
          x={200}
          y={210}
          width={120}
          fontSize={12}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
      {s.bothOn && (
        <Text text="MOTOR TRIPPED" x={200} y={226} width={120} fontSize={12} fontStyle="bold" fill={ALARM} />
      )}
      {s.overrunning && !s.crashed && (
        <Text
          text="OVERRUN"
          x={S.x - 20}
          y={s.position > 0 ? S.top + 2 : S.bottom - 16}
          width={S.w + 40}
          align="center"
          fontSize={14}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
      {s.crashed && (
        <Text
          text="CRASH"
          x={S.x - 20}
          y={s.position > 0 ? carBottom + 4 : carTop - 18}
          width={S.w + 40}
          align="center"
          fontSize={16}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
      {offFloor && (
        <Text
          text={`${Math.round(Math.abs(s.stopOffset))} mm ${s.stopOffset > 0 ? 'above' : 'below'} floor ${s.stopFloor}`}
          x={200}
          y={242}
          width={120}
          fontSize={11}
          fontStyle="bold"
          fill="#a16207"
        />
      )}
    </Group>
  );
}
