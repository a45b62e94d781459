// The centre of the editor: the open POUs' tabs, then the ladder canvas of the shown POU (or the
// ST editor of an ST POU, or the read-only source of a POU in another language or of a library
// block), or the editor of an open data type.
import { libraryInfo } from '../../model/codesysUtil';
import { selectActivePou, useDocument } from '../../store/documentStore';
import { LadderCanvas } from '../canvas/LadderCanvas';
import { DataTypeEditor } from '../dataTypes/DataTypeEditor';
import { useShownDataType } from '../dataTypes/dataTypeTabs';
import { StBodyView } from '../st/StBodyView';
import { PouTabs } from './PouTabs';
import { SourceView } from './SourceView';

export function PouView() {
  const pou = useDocument(selectActivePou);
  const dataType = useShownDataType();
  return (
    <div className="rs-pou-view">
      <PouTabs />
      <div className="rs-pou-body">
        {dataType ? (
          <DataTypeEditor name={dataType} />
        ) : pou && pou.language === 'ST' && !libraryInfo(pou) ? (
          <StBodyView key={pou.id} pou={pou} />
        ) : pou && pou.language !== 'LD' ? (
          <SourceView pou={pou} />
        ) : (
          <LadderCanvas key={pou?.id} />
        )}
      </div>
    </div>
  );
}
