// ESLint flat config for the ExtendScript files: parse every .jsx as an ES3 script (not React JSX).
// Run: npx eslint --config illustrator-scripts/eslint.config.js illustrator-scripts
export default [
  {
    files: ['**/*.jsx'],
    languageOptions: {
      ecmaVersion: 3,
      sourceType: 'script',
      parserOptions: { ecmaFeatures: { jsx: false } },
      globals: {
        app: 'readonly', alert: 'readonly', confirm: 'readonly', prompt: 'readonly', $: 'readonly', Window: 'readonly',
        RGBColor: 'readonly', NoColor: 'readonly', PointType: 'readonly', PathPointSelection: 'readonly',
        Transformation: 'readonly', RulerUnits: 'readonly', Justification: 'readonly',
        CoordinateSystem: 'readonly', DocumentColorSpace: 'readonly', StrokeCap: 'readonly', StrokeJoin: 'readonly', BlendModes: 'readonly',
        Object: 'readonly', Array: 'readonly', String: 'readonly', Number: 'readonly', Math: 'readonly', isFinite: 'readonly',
        parseInt: 'readonly', Infinity: 'readonly', NaN: 'readonly', undefined: 'readonly',
      },
    },
    rules: {
      'no-undef': 'error',
      'no-unused-vars': ['error', { vars: 'local', args: 'none', caughtErrors: 'none' }],
      'no-redeclare': 'error',
      'no-dupe-keys': 'error',
      'no-unreachable': 'error',
      // ES5+ library members that ExtendScript lacks (syntax is already limited by ecmaVersion 3).
      'no-restricted-properties': ['error',
        ...['forEach', 'map', 'filter', 'reduce', 'some', 'every', 'trim', 'isArray', 'keys', 'bind', 'toISOString']
          .map((property) => ({ property, message: `${property} is ES5+; ExtendScript is ES3.` })),
      ],
      'no-restricted-globals': ['error', { name: 'JSON', message: 'ExtendScript has no JSON object; use dformer_parse/dformer_stringify.' }],
    },
  },
];
