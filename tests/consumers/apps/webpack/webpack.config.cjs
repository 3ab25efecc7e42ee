// webpack 5 with nothing added: it bundles `new Worker(new URL('./worker.js', import.meta.url))`
// of @physin/worker into a chunk of its own. The test copies this file into the app's folder;
// modules resolve from that folder's node_modules only, so what is bundled is what npm installed
// from the tarballs.
const { join } = require('node:path');

module.exports = {
  mode: 'production',
  context: __dirname,
  entry: './main.js',
  output: { path: join(__dirname, 'dist'), filename: 'app.js', clean: true },
  resolve: { modules: [join(__dirname, 'node_modules')] },
  devtool: false,
  performance: { hints: false },
};
