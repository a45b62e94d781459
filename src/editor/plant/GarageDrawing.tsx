// The garage door, drawn with Konva from a GarageState (src/plant/garage.ts): the doorway seen
// from the drive, the door's sections at its position, the motor and its two contactors coloured
// by how they run, the limit switches and the photo-eye lit when ON (the beam red when broken),
// the warning lamp, the car in the doorway or waiting outside, and the consequences on the drawing.
import { Circle, Group, Line, Rect, Text } from 'react-konva';
import { CAR_TOP, CLOSED_LIMIT_AT, OPEN_LIMIT_AT, OVERRUN_MS, type GarageState } from '../../plant/garage';
import type { PlantDrawingProps } from './drawings';

export const GARAGE_SIZE = { width: 320, height: 270 } as const;

const LIT = '#22c55e';
const DARK = '#4b5563';
const OFF = '#e5e7eb';
const RAMP = '#eab308';
const ALARM = '#dc2626';
const TEXT = '#374151';
const DOOR = '#d6d3d1';

/** The doorway: x 70..230, y 44..224 (180 px for 100 % of its height). */
const D = { x: 70, y: 44, w: 160, h: 180 } as const;
const FLOOR = D.y + D.h;
const yOf = (percent: number) => FLOOR - (percent / 100) * D.h;
/** The door's sections, each a quarter of its height. */
const SECTION = D.h / 4;

function Indicator({
  x,
  y,
  on,
  label,
  color = LIT,
}: {
  x: number;
  y: number;
  on: boolean;
  label: string;
  color?: string;
}) {
  return (
    <Group x={x} y={y}>
      <Circle radius={6} fill={on ? color : OFF} stroke="#111827" strokeWidth={1} />
      <Text text={label} x={10} y={-5} fontSize={10} fill={TEXT} />
    </Group>
  );
}

/** A car seen from the front, `w` wide, its roof at `top`, standing on the floor. */
function Car({ x, w, top, faded }: { x: number; w: number; top: number; faded?: boolean }) {
  const h = FLOOR - top;
  return (
    <Group x={x} y={top} opacity={faded ? 0.55 : 1}>
      <Line
        points={[w * 0.2, 0, w * 0.8, 0, w * 0.92, h * 0.42, w * 0.08, h * 0.42]}
        closed
        fill="#1d4ed8"
        stroke="#111827"
        strokeWidth={1}
      />
      <Line
        points={[w * 0.25, h * 0.08, w * 0.75, h * 0.08, w * 0.84, h * 0.38, w * 0.16, h * 0.38]}
        closed
        fill="#bfdbfe"
      />
      <Rect
        y={h * 0.42}
        width={w}
        height={h * 0.4}
        fill="#2563eb"
        stroke="#111827"
        strokeWidth={1}
        cornerRadius={4}
      />
      <Circle
        x={w * 0.14}
        y={h * 0.6}
        radius={Math.max(3, w * 0.06)}
        fill="#fef9c3"
        stroke="#111827"
        strokeWidth={1}
      />
      <Circle
        x={w * 0.86}
        y={h * 0.6}
        radius={Math.max(3, w * 0.06)}
        fill="#fef9c3"
        stroke="#111827"
        strokeWidth={1}
      />
      <Rect x={w * 0.06} y={h * 0.82} width={w * 0.16} height={h * 0.18} fill="#111827" />
      <Rect x={w * 0.78} y={h * 0.82} width={w * 0.16} height={h * 0.18} fill="#111827" />
    </Group>
  );
}

export function GarageDrawing({ state, sensed }: PlantDrawingProps) {
  const s = state as GarageState;
  const edge = yOf(s.position);
  // Energised but not at speed (starting, or stalled against a stop or on the car): amber, as a
  // motor whose contactor is on; dark only with both contactors off and the door still.
  const energised = s.up || s.down;
  const motorColor = s.short ? ALARM : Math.abs(s.speed) > 0.99 ? LIT : s.speed !== 0 || energised ? RAMP : DARK;
  const overrun = s.pushMs > OVERRUN_MS;
  // Section joints move with the door: they sit a whole section apart, up from its edge.
  const joints: number[] = [];
  for (let y = edge - SECTION; y > D.y; y -= SECTION) joints.push(y);
  return (
    <Group>
      {/* The wall and the lintel over the doorway. */}
      <Rect x={0} y={D.y - 8} width={GARAGE_SIZE.width} height={D.h + 8} fill="#f5f5f4" />
      <Rect x={D.x - 6} y={D.y - 8} width={D.w + 12} height={8} fill="#a8a29e" />
      {/* Inside the garage, seen under the door. */}
      <Rect x={D.x} y={D.y} width={D.w} height={D.h} fill="#1f2937" />
      {s.carIn && <Car x={D.x + 20} w={D.w - 40} top={yOf(CAR_TOP)} />}
      {s.carWaiting && !s.carIn && <Car x={D.x + D.w + 14} w={70} top={yOf(CAR_TOP)} faded />}
      {/* The door, down to its edge. */}
      {edge > D.y + 0.5 && (
        <Group>
          <Rect
            x={D.x}
            y={D.y}
            width={D.w}
            height={edge - D.y}
            fill={DOOR}
            stroke={s.onCar ? ALARM : '#78716c'}
            strokeWidth={s.onCar ? 3 : 1}
          />
          {joints.map((y) => (
            <Line key={y} points={[D.x, y, D.x + D.w, y]} stroke="#78716c" strokeWidth={1} />
          ))}
          <Rect x={D.x + D.w / 2 - 12} y={edge - 10} width={24} height={4} fill="#57534e" />
        </Group>
      )}
      {/* Jambs and floor. */}
      <Rect x={D.x - 6} y={D.y} width={6} height={D.h} fill="#a8a29e" />
      <Rect x={D.x + D.w} y={D.y} width={6} height={D.h} fill="#a8a29e" />
      <Line points={[0, FLOOR, GARAGE_SIZE.width, FLOOR]} stroke="#111827" strokeWidth={2} />
      {/* The photo-eye across the doorway, near the floor; the beam red when the car breaks it, the
          receiver's lamp as the program reads it (a stuck eye sees no car in the beam). */}
      <Line
        points={[D.x + 2, FLOOR - 14, D.x + D.w - 2, FLOOR - 14]}
        stroke={s.carIn ? ALARM : '#86efac'}
        strokeWidth={s.carIn ? 2 : 1}
        dash={[4, 3]}
      />
      <Rect
        x={D.x - 10}
        y={FLOOR - 19}
        width={8}
        height={10}
        fill={(sensed ? sensed.Obstacle === true : s.carIn) ? LIT : OFF}
        stroke="#111827"
        strokeWidth={1}
      />
      <Rect
        x={D.x + D.w + 2}
        y={FLOOR - 19}
        width={8}
        height={10}
        fill={OFF}
        stroke="#111827"
        strokeWidth={1}
      />
      <Text text="photo-eye" x={D.x} y={FLOOR + 4} width={D.w} align="center" fontSize={10} fill={TEXT} />
      {/* The limit switches on the left track. */}
      {/* Lit as the program reads them, faults applied (a switch stuck OFF stays dark at its stop). */}
      <Indicator x={14} y={D.y + 6} on={sensed ? sensed.OpenLimit === true : s.position >= OPEN_LIMIT_AT} label="Open" />
      <Indicator x={14} y={FLOOR - 8} on={sensed ? sensed.ClosedLimit === true : s.position <= CLOSED_LIMIT_AT} label="Closed" />
      <Line points={[56, D.y + 16, 56, FLOOR - 18]} stroke="#d6d3d1" strokeWidth={2} />
      <Line points={[50, edge, 62, edge]} stroke="#57534e" strokeWidth={3} />
      {/* The motor over the doorway, its contactors beside it. */}
      <Group x={D.x + D.w / 2} y={18}>
        <Rect
          x={-22}
          y={-12}
          width={44}
          height={24}
          cornerRadius={4}
          fill={motorColor}
          stroke="#111827"
          strokeWidth={1}
        />
        {s.speed > 0 && <Line points={[-6, 5, 0, -6, 6, 5]} closed fill="#f9fafb" />}
        {s.speed < 0 && <Line points={[-6, -5, 0, 6, 6, -5]} closed fill="#f9fafb" />}
        <Text text="Motor" x={-62} y={-5} width={36} align="right" fontSize={10} fill={TEXT} />
      </Group>
      <Indicator x={D.x + D.w / 2 + 32} y={11} on={s.up} label="Up" color={s.short ? ALARM : LIT} />
      <Indicator x={D.x + D.w / 2 + 32} y={26} on={s.down} label="Down" color={s.short ? ALARM : LIT} />
      {/* The warning lamp. */}
      <Circle x={282} y={14} radius={9} fill={s.lamp ? '#f97316' : OFF} stroke="#111827" strokeWidth={1} />
      <Text text="Warning" x={252} y={25} width={60} align="center" fontSize={10} fill={TEXT} />
      <Text
        text={`${s.position.toFixed(1)} % open`}
        x={4}
        y={6}
        fontSize={13}
        fontStyle="bold"
        fill="#111827"
      />
      {/* Consequences on the drawing. */}
      {s.onCar && (
        <Text
          text="HIT THE CAR"
          x={D.x}
          y={edge - 36}
          width={D.w}
          align="center"
          fontSize={14}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
      {s.short && (
        <Text
          text="SHORT CIRCUIT"
          x={D.x - 40}
          y={D.y + 24}
          width={D.w + 80}
          align="center"
          fontSize={13}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
      {overrun && (
        <Text
          text={s.position >= 100 ? 'OVERRUN (open end)' : 'OVERRUN (closed end)'}
          x={D.x - 40}
          y={D.y + 40}
          width={D.w + 80}
          align="center"
          fontSize={13}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
      {s.unwarnedNow && (
        <Text
          text="NO WARNING"
          x={D.x + D.w + 10}
          y={D.y + 6}
          fontSize={10}
          fontStyle="bold"
          fill="#a16207"
        />
      )}
    </Group>
  );
}
