// The Project tree's Libraries section: the libraries kept with the project and their blocks (a
// click shows a block read-only in the library manager), and the button that opens the manager.
import { selectProject, useDocument } from '../../store/documentStore';
import { libraryUi, openLibraryManager } from './libraryUi';

export function LibrariesSection() {
  const project = useDocument(selectProject);
  const libraries = project.libraries ?? [];
  return (
    <li className="rs-tree-section">
      <span className="rs-tree-heading">
        Libraries <span className="rs-tree-count">{libraries.length}</span>
        <button
          type="button"
          className="rs-icon-button"
          data-testid="tree-libraries"
          title="Library manager: add, update or remove libraries; OpenPLC's vendor libraries"
          onClick={openLibraryManager}
        >
          ⚙
        </button>
      </span>
      <ul aria-label="Libraries">
        {libraries.map((lib) => (
          <li key={lib.name} className="rs-tree-task" data-testid={`tree-library-${lib.name}`}>
            <span className="rs-mono">{lib.name}</span> <span className="rs-tree-detail">{lib.sourceFile}</span>
            <ul>
              {lib.pous.map((p) => (
                <li key={p.id} className="rs-tree-detail">
                  <button
                    type="button"
                    className="rs-tree-node"
                    title={`${p.name}: a ${p.kind === 'FUNCTION' ? 'function' : 'function block'} of the library ${lib.name} (read-only); click to view it`}
                    onClick={() => {
                      openLibraryManager();
                      libraryUi.getState().setViewing(p.id);
                    }}
                  >
                    <span className="rs-mono">{p.name}</span> <span className="rs-tree-lang">{p.kind === 'FUNCTION' ? 'fn' : 'FB'}</span>
                  </button>
                </li>
              ))}
            </ul>
          </li>
        ))}
      </ul>
    </li>
  );
}
