import js from '@eslint/js';
import tseslint from 'typescript-eslint';
import reactHooks from 'eslint-plugin-react-hooks';
import globals from 'globals';

// Layering (ARCHITECTURE.md): lower layers never import upper ones or UI/server libraries.
const uiAndServer = ['react', 'react-dom', 'react-dom/*', 'konva', 'konva/*', 'react-konva', 'zustand', 'zustand/*', 'ws', 'modbus-serial', 'uplot'];
const layer = (forbiddenDirs, forbiddenPkgs = uiAndServer) => ({
  'no-restricted-imports': [
    'error',
    {
      patterns: [
        ...forbiddenDirs.map((d) => ({ group: [`**/${d}/*`, `**/${d}`], message: `This layer must not import src/${d} (see ARCHITECTURE.md).` })),
        { group: forbiddenPkgs, message: 'The core stays free of React, DOM, Konva and server libraries.' },
      ],
    },
  ],
});
const above = {
  model: ['engine', 'plcopen', 'cli', 'sim', 'store', 'editor', 'bridge', 'gateway', 'protocol'],
  engine: ['plcopen', 'cli', 'sim', 'store', 'editor', 'bridge', 'gateway', 'protocol'],
  plcopen: ['cli', 'sim', 'store', 'editor', 'bridge', 'gateway', 'protocol'],
  protocol: ['engine', 'plcopen', 'cli', 'sim', 'store', 'editor', 'bridge', 'gateway'],
  // Machines to control (issue 26) know the PLC only as an I/O image: below the engine's users.
  plant: ['engine', 'plcopen', 'cli', 'sim', 'store', 'editor', 'bridge', 'gateway', 'protocol'],
};

export default tseslint.config(
  { ignores: ['dist/**', 'node_modules/**', 'coverage/**'] },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  {
    languageOptions: { globals: { ...globals.browser, ...globals.node } },
    rules: {
      '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_', varsIgnorePattern: '^_' }],
      'no-constant-condition': ['error', { checkLoops: false }],
    },
  },
  { files: ['src/**/*.{ts,tsx}'], plugins: { 'react-hooks': reactHooks }, rules: { 'react-hooks/rules-of-hooks': 'error', 'react-hooks/exhaustive-deps': 'warn' } },
  { files: ['src/model/**/*.ts'], rules: layer(above.model) },
  { files: ['src/engine/**/*.ts'], rules: layer(above.engine) },
  { files: ['src/plcopen/**/*.ts'], rules: layer(above.plcopen) },
  { files: ['src/plant/**/*.ts'], rules: layer(above.plant) },
  { files: ['src/protocol/**/*.ts'], rules: layer(above.protocol, ['react', 'react-dom', 'konva', 'react-konva', 'zustand', 'ws', 'modbus-serial']) },
);
