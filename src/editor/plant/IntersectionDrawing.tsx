// The road intersection, drawn with Konva from an IntersectionState (src/plant/intersection.ts),
// seen from above: the main road (north-south) and the side road (east-west), the cars queued at
// each stop line over its detector loop (lit while a car stands on it), the car crossing, each
// road's signal head (a burnt-out lamp crossed out), the pedestrian crossings with their WALK and
// DON'T WALK lamps, the pedestrians waiting and crossing, and the consequences on the drawing.
import { Circle, Group, Line, Rect, Text } from 'react-konva';
import {
  CLEAR_MS,
  CROSS_MAIN_MS,
  CROSS_SIDE_MS,
  HEAD,
  LAMP,
  VEHICLE_WAIT_LIMIT_MS,
  type IntersectionState,
} from '../../plant/intersection';
import type { PlantDrawingProps } from './drawings';

export const INTERSECTION_SIZE = { width: 320, height: 340 } as const;
/** The road scene; below it the strip where the panel places the pedestrians' push buttons. */
const SCENE_H = 302;

const ROAD_FILL = '#6b7280';
const GRASS = '#ecfccb';
const MARK = '#f9fafb';
const DARK = '#374151';
const ALARM = '#dc2626';
const CAR = '#2563eb';
const SIDE_CAR = '#7c3aed';
const PED = '#f97316';

/** The main road x 130..190, the side road y 130..180; the box where they cross. */
const M = { x: 130, w: 60 } as const;
const S = { y: 130, h: 50 } as const;
/** How many queued cars are drawn before "+N". */
const SHOWN = 4;

const has = (bits: number, mask: number) => (bits & mask) !== 0;

/** One lamp: lit in its colour, dark, or driven but burnt out (crossed out). */
function Lamp({
  x,
  y,
  colour,
  lamps,
  lit,
  bit,
}: {
  x: number;
  y: number;
  colour: string;
  lamps: number;
  lit: number;
  bit: number;
}) {
  const burnt = has(lamps, bit) && !has(lit, bit);
  return (
    <Group x={x} y={y}>
      <Circle radius={7} fill={has(lit, bit) ? colour : '#1f2937'} stroke="#000" strokeWidth={1} />
      {burnt && <Line points={[-5, -5, 5, 5, 0, 0, 5, -5, -5, 5]} stroke={ALARM} strokeWidth={2} />}
    </Group>
  );
}

function SignalHead({
  x,
  y,
  road,
  s,
  label,
}: {
  x: number;
  y: number;
  road: 'Main' | 'Side';
  s: IntersectionState;
  label: string;
}) {
  const dark = has(s.dark, road === 'Main' ? HEAD.Main : HEAD.Side);
  return (
    <Group x={x} y={y}>
      <Rect x={-10} y={-10} width={20} height={52} cornerRadius={3} fill="#111827" />
      <Lamp x={0} y={0} colour="#ef4444" lamps={s.lamps} lit={s.lit} bit={LAMP[`${road}Red`]} />
      <Lamp x={0} y={16} colour="#facc15" lamps={s.lamps} lit={s.lit} bit={LAMP[`${road}Yellow`]} />
      <Lamp x={0} y={32} colour="#22c55e" lamps={s.lamps} lit={s.lit} bit={LAMP[`${road}Green`]} />
      <Text text={label} x={-24} y={45} width={48} align="center" fontSize={12} fontStyle="bold" fill={DARK} />
      {dark && (
        <Text
          text="DARK"
          x={-24}
          y={-24}
          width={48}
          align="center"
          fontSize={11}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
    </Group>
  );
}

/** WALK / DON'T WALK lamps of one crossing. */
function PedHead({
  x,
  y,
  crossing,
  s,
}: {
  x: number;
  y: number;
  crossing: 'Main' | 'Side';
  s: IntersectionState;
}) {
  const walk = has(s.lit, LAMP[`Walk${crossing}`]);
  const dont = has(s.lit, LAMP[`DontWalk${crossing}`]);
  const dark = has(s.dark, crossing === 'Main' ? HEAD.PedMain : HEAD.PedSide);
  return (
    <Group x={x} y={y}>
      <Rect width={44} height={30} cornerRadius={3} fill="#111827" />
      <Text
        text="WALK"
        x={2}
        y={3}
        width={40}
        align="center"
        fontSize={10}
        fontStyle="bold"
        fill={walk ? '#4ade80' : '#374151'}
      />
      <Text
        text="DON'T"
        x={2}
        y={16}
        width={40}
        align="center"
        fontSize={10}
        fontStyle="bold"
        fill={dont ? '#fb923c' : '#374151'}
      />
      {dark && (
        <Text
          text="DARK"
          x={0}
          y={-13}
          width={44}
          align="center"
          fontSize={11}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
    </Group>
  );
}

/** A car seen from above, `dir` the way it drives. */
function Car({ x, y, dir, fill }: { x: number; y: number; dir: 'north' | 'east'; fill: string }) {
  const [w, h] = dir === 'north' ? [14, 22] : [22, 14];
  return (
    <Rect
      x={x - w / 2}
      y={y - h / 2}
      width={w}
      height={h}
      cornerRadius={3}
      fill={fill}
      stroke="#1e1b4b"
      strokeWidth={1}
    />
  );
}

/** Pedestrians as dots: `n` of them around (x, y). */
function People({ x, y, n }: { x: number; y: number; n: number }) {
  const dots = Math.min(n, 4);
  return (
    <Group>
      {Array.from({ length: dots }, (_, i) => (
        <Circle
          key={i}
          x={x + (i % 2) * 8}
          y={y + Math.floor(i / 2) * 8}
          radius={3.5}
          fill={PED}
          stroke="#7c2d12"
          strokeWidth={1}
        />
      ))}
      {n > dots && <Text text={`+${n - dots}`} x={x + 16} y={y - 2} fontSize={10} fill={DARK} />}
    </Group>
  );
}

export function IntersectionDrawing({ state, sensed }: PlantDrawingProps) {
  const s = state as IntersectionState;
  const waitingMain = s.arrivedMain - s.departedMain;
  const waitingSide = s.arrivedSide - s.departedSide;
  // Cars still in the box: the last to leave each stop line, CLEAR_MS ago at most.
  const mainIn = (s.timeMs - s.lastMainMs) / CLEAR_MS;
  const sideIn = (s.timeMs - s.lastSideMs) / CLEAR_MS;
  // Lane centres: northbound main road cars in its right lane, eastbound side road cars in its lower lane.
  const mainLane = M.x + (M.w * 3) / 4;
  const sideLane = S.y + (S.h * 3) / 4;
  const mainStop = S.y + S.h + 22;
  const sideStop = M.x - 30;
  const alarm: string[] = [];
  if (s.conflict) alarm.push('CONFLICT');
  if (s.box) alarm.push('NEAR MISS');
  if (s.caught) alarm.push('PEDESTRIANS CAUGHT');
  return (
    <Group>
      <Rect width={INTERSECTION_SIZE.width} height={INTERSECTION_SIZE.height} fill={GRASS} />
      {/* The roads, their centre lines and the stop lines. */}
      <Rect x={M.x} y={0} width={M.w} height={SCENE_H} fill={ROAD_FILL} />
      <Rect x={0} y={S.y} width={INTERSECTION_SIZE.width} height={S.h} fill={ROAD_FILL} />
      <Line points={[M.x + M.w / 2, 0, M.x + M.w / 2, S.y]} stroke={MARK} strokeWidth={1} dash={[8, 6]} />
      <Line
        points={[M.x + M.w / 2, S.y + S.h, M.x + M.w / 2, SCENE_H]}
        stroke={MARK}
        strokeWidth={1}
        dash={[8, 6]}
      />
      <Line points={[0, S.y + S.h / 2, M.x, S.y + S.h / 2]} stroke={MARK} strokeWidth={1} dash={[8, 6]} />
      <Line
        points={[M.x + M.w, S.y + S.h / 2, INTERSECTION_SIZE.width, S.y + S.h / 2]}
        stroke={MARK}
        strokeWidth={1}
        dash={[8, 6]}
      />
      <Line points={[M.x + M.w / 2, S.y + S.h + 6, M.x + M.w, S.y + S.h + 6]} stroke={MARK} strokeWidth={3} />
      <Line points={[M.x - 6, S.y + S.h / 2, M.x - 6, S.y + S.h]} stroke={MARK} strokeWidth={3} />
      <Text text="Main road" x={M.x + M.w + 4} y={SCENE_H - 16} fontSize={11} fill={DARK} />
      <Text text="Side road" x={6} y={S.y - 14} fontSize={11} fill={DARK} />
      {/* Crossings: over the main road north of the box, over the side road east of it. */}
      {Array.from({ length: 6 }, (_, i) => (
        <Rect key={`zm${i}`} x={M.x + 3 + i * 10} y={S.y - 22} width={5} height={16} fill={MARK} />
      ))}
      {Array.from({ length: 5 }, (_, i) => (
        <Rect key={`zs${i}`} x={M.x + M.w + 6} y={S.y + 3 + i * 10} width={16} height={5} fill={MARK} />
      ))}
      {/* Detector loops at the stop lines, lit while the loop reads ON (a car stands on it, or a fault holds it). */}
      <Rect
        x={mainLane - 10}
        y={mainStop - 14}
        width={20}
        height={28}
        stroke={(sensed ? sensed.LoopMain === true : waitingMain > 0) ? '#facc15' : '#d1d5db'}
        strokeWidth={2}
        dash={[3, 2]}
      />
      <Rect
        x={sideStop - 14}
        y={sideLane - 10}
        width={28}
        height={20}
        stroke={(sensed ? sensed.LoopSide === true : waitingSide > 0) ? '#facc15' : '#d1d5db'}
        strokeWidth={2}
        dash={[3, 2]}
      />
      {/* Queues. */}
      {Array.from({ length: Math.min(waitingMain, SHOWN) }, (_, i) => (
        <Car key={`qm${i}`} x={mainLane} y={mainStop + i * 28} dir="north" fill={CAR} />
      ))}
      {waitingMain > SHOWN && (
        <Text
          text={`+${waitingMain - SHOWN}`}
          x={M.x + 4}
          y={mainStop + (SHOWN - 1) * 28 - 6}
          fontSize={11}
          fontStyle="bold"
          fill={MARK}
        />
      )}
      {Array.from({ length: Math.min(waitingSide, SHOWN) }, (_, i) => (
        <Car key={`qs${i}`} x={sideStop - i * 28} y={sideLane} dir="east" fill={SIDE_CAR} />
      ))}
      {waitingSide > SHOWN && (
        <Text text={`+${waitingSide - SHOWN}`} x={2} y={S.y + S.h + 4} fontSize={11} fill={DARK} />
      )}
      {/* Cars crossing the box. */}
      {mainIn >= 0 && mainIn < 1 && (
        <Car x={mainLane} y={mainStop - 20 - mainIn * (S.h + 40)} dir="north" fill={CAR} />
      )}
      {sideIn >= 0 && sideIn < 1 && (
        <Car x={sideStop + 24 + sideIn * (M.w + 40)} y={sideLane} dir="east" fill={SIDE_CAR} />
      )}
      {/* Signal heads at the stop lines, pedestrian lamps at the crossings. */}
      <SignalHead x={M.x + M.w + 18} y={S.y + S.h + 20} road="Main" s={s} label="Main" />
      <SignalHead x={M.x - 18} y={S.y + S.h + 20} road="Side" s={s} label="Side" />
      <PedHead x={M.x - 50} y={S.y - 50} crossing="Main" s={s} />
      <PedHead x={M.x + M.w + 30} y={S.y - 50} crossing="Side" s={s} />
      <Text text="cross main" x={M.x - 72} y={S.y - 64} width={72} align="center" fontSize={11} fill={DARK} />
      <Text
        text="cross side"
        x={M.x + M.w + 22}
        y={S.y - 64}
        width={72}
        align="center"
        fontSize={11}
        fill={DARK}
      />
      {/* Pedestrians waiting at the kerb, and crossing. */}
      <People x={M.x - 16} y={S.y - 16} n={s.pedWaitMain} />
      <People x={M.x + M.w + 34} y={S.y + S.h + 6} n={s.pedWaitSide} />
      {s.pedOnMain > 0 && (
        <Circle
          x={M.x + M.w * (1 - s.pedOnMain / CROSS_MAIN_MS)}
          y={S.y - 14}
          radius={4.5}
          fill={PED}
          stroke="#7c2d12"
          strokeWidth={1}
        />
      )}
      {s.pedOnSide > 0 && (
        <Circle
          x={M.x + M.w + 14}
          y={S.y + S.h - S.h * (1 - s.pedOnSide / CROSS_SIDE_MS)}
          radius={4.5}
          fill={PED}
          stroke="#7c2d12"
          strokeWidth={1}
        />
      )}
      {/* Counts, and long waits at the queues. */}
      <Text
        text={`Served: main ${s.departedMain}, side ${s.departedSide}\nWaiting: main ${waitingMain}, side ${waitingSide}\nPedestrians across: ${s.pedServed}`}
        x={M.x + M.w + 6}
        y={4}
        width={INTERSECTION_SIZE.width - M.x - M.w - 8}
        fontSize={10}
        lineHeight={1.3}
        fill={DARK}
      />
      {s.longSide > s.departedSide && (
        <Text
          text={`WAIT > ${VEHICLE_WAIT_LIMIT_MS / 1000} s`}
          x={4}
          y={S.y + S.h + 18}
          fontSize={11}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
      {s.longMain > s.departedMain && (
        <Text
          text={`WAIT > ${VEHICLE_WAIT_LIMIT_MS / 1000} s`}
          x={M.x + M.w + 36}
          y={S.y + S.h + 74}
          fontSize={11}
          fontStyle="bold"
          fill={ALARM}
        />
      )}
      {(s.pedLongMain || s.pedLongSide) && (
        <Text text="PEDESTRIAN WAIT > 60 s" x={4} y={4} fontSize={11} fontStyle="bold" fill={ALARM} />
      )}
      {alarm.length > 0 && (
        <Group>
          <Rect x={M.x} y={S.y} width={M.w} height={S.h} stroke={ALARM} strokeWidth={3} />
          {/* The alarm on a label over the box, readable whatever is under it. */}
          <Rect
            x={M.x + M.w / 2 - 66}
            y={S.y + S.h / 2 - 8 * alarm.length - 3}
            width={132}
            height={16 * alarm.length + 6}
            fill="#fff"
            stroke={ALARM}
            strokeWidth={2}
            cornerRadius={3}
          />
          <Text
            text={alarm.join('\n')}
            x={M.x + M.w / 2 - 66}
            y={S.y + S.h / 2 - 8 * alarm.length + 1}
            width={132}
            align="center"
            fontSize={12}
            lineHeight={16 / 12}
            fontStyle="bold"
            fill={ALARM}
          />
        </Group>
      )}
      {/* The strip the pedestrians' push buttons sit on (the panel places them at its left). */}
      <Rect
        y={SCENE_H}
        width={INTERSECTION_SIZE.width}
        height={INTERSECTION_SIZE.height - SCENE_H}
        fill="#e5e7eb"
        stroke="#9ca3af"
        strokeWidth={1}
      />
      <Text
        text="pedestrian push buttons"
        x={INTERSECTION_SIZE.width - 134}
        y={SCENE_H + 14}
        width={130}
        align="right"
        fontSize={10}
        fill={DARK}
      />
    </Group>
  );
}
