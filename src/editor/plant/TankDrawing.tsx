// The tank, drawn with Konva from a TankState (src/plant/tank.ts): the vessel with its water,
// the float switches lit when ON, the pump and valves coloured by how far they run or open,
// the pipes blue while water flows, the run lamp, and overflow / dry shown on the drawing.
import { Circle, Group, Line, Rect, Text } from 'react-konva';
import { HIGH_SWITCH_L, LOW_SWITCH_L, TANK_CAPACITY_L, type TankState } from '../../plant/tank';
import type { PlantDrawingProps } from './drawings';

export const TANK_SIZE = { width: 300, height: 250 } as const;

const WATER = '#3b82f6';
const PIPE = '#9ca3af';
const LIT = '#22c55e';
const DARK = '#4b5563';
const ALARM = '#dc2626';

/** The vessel: x 110..210, y 40..220 (180 px for 1,000 L). */
const V = { x: 110, y: 40, w: 100, h: 180 } as const;
const yOf = (litres: number) => V.y + V.h - (litres / TANK_CAPACITY_L) * V.h;

function Valve({ x, y, open, label }: { x: number; y: number; open: number; label: string }) {
  const fill = open > 0.99 ? LIT : open > 0.01 ? '#eab308' : DARK;
  return (
    <Group x={x} y={y}>
      <Line points={[-10, -8, 10, 8, 10, -8, -10, 8]} closed fill={fill} stroke="#111827" strokeWidth={1} />
      <Text text={label} x={-30} y={11} width={60} align="center" fontSize={10} fill="#374151" />
    </Group>
  );
}

function FloatSwitch({ litres, on, label }: { litres: number; on: boolean; label: string }) {
  const y = yOf(litres);
  return (
    <Group>
      <Line points={[V.x + V.w, y, V.x + V.w + 14, y]} stroke={DARK} strokeWidth={2} />
      <Circle
        x={V.x + V.w + 20}
        y={y}
        radius={6}
        fill={on ? LIT : '#e5e7eb'}
        stroke="#111827"
        strokeWidth={1}
      />
      <Text text={label} x={V.x + V.w + 30} y={y - 6} fontSize={11} fill="#111827" />
    </Group>
  );
}

export function TankDrawing({ state, sensed }: PlantDrawingProps) {
  const s = state as TankState;
  const top = yOf(s.level);
  const inflowing = s.inflow > 0;
  const outflowing = s.outflow > 0;
  return (
    <Group>
      {/* Feed: source -> pump -> inlet valve -> over the rim. */}
      <Line
        points={[10, 20, 60, 20, 150, 20, 150, V.y + 6]}
        stroke={inflowing ? WATER : PIPE}
        strokeWidth={6}
      />
      <Group x={40} y={20}>
        <Circle
          radius={14}
          fill={s.pump > 0.99 ? LIT : s.pump > 0.01 ? '#eab308' : DARK}
          stroke="#111827"
          strokeWidth={1}
        />
        <Line points={[-6, -8, 8, 0, -6, 8]} closed fill="#f9fafb" />
        <Text text="Pump" x={-20} y={16} width={40} align="center" fontSize={10} fill="#374151" />
      </Group>
      <Valve x={100} y={20} open={s.inlet} label="Inlet" />
      {inflowing && (
        <Rect x={147} y={V.y + 6} width={6} height={Math.max(0, top - V.y - 6)} fill={WATER} opacity={0.6} />
      )}
      {/* Vessel and water. */}
      <Rect x={V.x} y={V.y} width={V.w} height={V.h} stroke="#111827" strokeWidth={2} fill="#f3f4f6" />
      <Rect x={V.x + 1} y={top} width={V.w - 2} height={V.y + V.h - top - 1} fill={WATER} opacity={0.85} />
      <Text
        text={`${Math.round(s.level)} L`}
        x={V.x}
        y={V.y + V.h / 2 - 8}
        width={V.w}
        align="center"
        fontSize={14}
        fontStyle="bold"
        fill="#111827"
      />
      <FloatSwitch
        litres={HIGH_SWITCH_L}
        on={sensed ? sensed.HighLevel === true : s.level >= HIGH_SWITCH_L}
        label="High"
      />
      <FloatSwitch
        litres={LOW_SWITCH_L}
        on={sensed ? sensed.LowLevel === true : s.level >= LOW_SWITCH_L}
        label="Low"
      />
      {/* Drain to the process. */}
      <Line
        points={[V.x + V.w / 2, V.y + V.h, V.x + V.w / 2, 236, 290, 236]}
        stroke={outflowing ? WATER : PIPE}
        strokeWidth={6}
      />
      <Valve x={250} y={236} open={s.drain} label="" />
      <Text text="Drain" x={236} y={216} fontSize={10} fill="#374151" />
      {/* Run lamp. */}
      <Circle
        x={30}
        y={120}
        radius={11}
        fill={s.lamp ? '#facc15' : '#e5e7eb'}
        stroke="#111827"
        strokeWidth={1}
      />
      <Text text="Run" x={10} y={134} width={40} align="center" fontSize={10} fill="#374151" />
      {/* Consequences on the drawing. */}
      {s.overflowing && (
        <Group>
          <Line points={[V.x, V.y, V.x - 12, V.y + 40]} stroke={WATER} strokeWidth={4} />
          <Line points={[V.x + V.w, V.y, V.x + V.w + 12, V.y + 40]} stroke={WATER} strokeWidth={4} />
          <Text
            text="OVERFLOW"
            x={V.x - 20}
            y={V.y - 32}
            width={V.w + 40}
            align="center"
            fontSize={14}
            fontStyle="bold"
            fill={ALARM}
          />
        </Group>
      )}
      {s.dry && (
        <Text
          text="RUN DRY"
          x={V.x - 20}
          y={V.y + V.h - 30}
          width={V.w + 40}
          align="center"
          fontSize={14}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
    </Group>
  );
}
