// A build of the app with React's profiling renderer, unminified, for bench/editorProfile.ts's
// REACT_RENDERS=1 (which components a click renders and their own render time needs the fiber
// timings only the profiling build keeps):
//   npx vite build -c bench/vite.profiling.config.ts --outDir /tmp/profr
//   RUNGSMITH_DIST=/tmp/profr REACT_RENDERS=1 npx tsx bench/editorProfile.ts clicks bottle
import { defineConfig, mergeConfig } from 'vite';
import base from '../vite.config';

export default mergeConfig(
  base,
  defineConfig({
    resolve: { alias: [{ find: /^react-dom\/client$/, replacement: 'react-dom/profiling' }] },
    build: { minify: false },
  }),
);
