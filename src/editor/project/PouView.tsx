// The centre of the editor: the open POUs' tabs, then the ladder canvas of the shown POU (or the
// read-only source of a POU in another language).
import { selectActivePou, useDocument } from '../../store/documentStore';
import { LadderCanvas } from '../canvas/LadderCanvas';
import { PouTabs } from './PouTabs';
import { SourceView } from './SourceView';

export function PouView() {
  const pou = useDocument(selectActivePou);
  return (
    <div className="rs-pou-view">
      <PouTabs />
      <div className="rs-pou-body">
        {pou && pou.language !== 'LD' ? <SourceView pou={pou} /> : <LadderCanvas key={pou?.id} />}
      </div>
    </div>
  );
}
