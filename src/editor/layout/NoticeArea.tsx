// The one place for notices (online change, edit not applied, breakpoint, fault, file and import
// notices): a band between the tool bar and the workspace, in the layout flow. A notice pushes the
// workspace down a line instead of covering the POU tabs, the palette or the tool bar; long words
// wrap inside the window; many notices scroll inside the band, which never takes more than a
// quarter of the window.
import { Fragment } from 'react';
import { NOTICES } from './panels';

export function NoticeArea() {
  return (
    <section className="rs-notices" aria-label="Notices" data-testid="notices">
      {NOTICES.map(({ id, component: Item }) => (
        <Fragment key={id}>
          <Item />
        </Fragment>
      ))}
    </section>
  );
}
