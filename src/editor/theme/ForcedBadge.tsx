// The forced-value badge of the panels: the same square, letter and colour the canvas draws (FORCED_BADGE).
import { FORCED_BADGE } from './monitorStyle';

const STYLE = {
  display: 'inline-block',
  width: FORCED_BADGE.size,
  height: FORCED_BADGE.size,
  lineHeight: `${FORCED_BADGE.size}px`,
  font: FORCED_BADGE.font,
  textAlign: 'center',
  verticalAlign: 'middle',
  marginLeft: 2,
  background: `var(${FORCED_BADGE.colourVar})`,
  color: FORCED_BADGE.letterColour,
} as const;

export function ForcedBadge({ title }: { readonly title?: string }) {
  // A space before it: the value reads "42 F" as text (screen readers, copy).
  return (
    <>
      {' '}
      <span className="rs-forced-badge" data-testid="forced-badge" style={STYLE} title={title ?? FORCED_BADGE.title}>
        {FORCED_BADGE.letter}
      </span>
    </>
  );
}
