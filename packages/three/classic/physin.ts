/**
 * The classic-script build (the specification's sections 2 and 3): `physin.js` puts `PhysiN` on
 * the global object, with the adapter under the specification's names, the engine as
 * `PhysiN.nd`, and `PhysiN.scripts.worker` choosing the thread: null (the default) steps in the
 * page's thread; a file name runs `physin_worker.js` in a worker over HTTP, and from `file://`,
 * where a worker cannot load a file, a worker started from a Blob URL holding the same code.
 *
 * Built by classic/build.mjs with three.js as the global `THREE`.
 */
import * as nd from '@physin/engine';
import { Scene as ModuleScene } from '../dist/index.js';
import type { SceneOptions } from '../dist/index.js';

export {
  BoxMesh,
  SphereMesh,
  PlaneMesh,
  TorusMesh,
  ConvexMesh,
  Mesh,
  HyperBoxMesh,
  HyperSphereMesh,
  HyperPlaneMesh,
  HyperTorusMesh,
  HyperMesh,
  PointJoint,
  DistanceJoint,
  FixedJoint,
  HingeJoint,
  SubspaceJoint,
  createMaterial,
} from '../dist/index.js';
export { nd };

/** Where the worker script is, as the page sees it; null steps the world in the page's thread. */
export const scripts: { worker: string | null } = { worker: null };

/** The text of physin_worker.js, put here by the build (for a Blob-URL worker). */
declare const __PHYSIN_WORKER_SOURCE__: string;
let blobUrl: string | null = null;

/** The worker for a new scene: none, the file over HTTP, or (from file://) the inlined copy. */
function chooseWorker(): SceneOptions['worker'] {
  if (scripts.worker === null) return false;
  if (window.location.protocol === 'file:') {
    // a page opened from disk cannot start a worker from a file: the same code from a Blob URL
    blobUrl ??= URL.createObjectURL(new Blob([__PHYSIN_WORKER_SOURCE__], { type: 'text/javascript' }));
    return new Worker(blobUrl);
  }
  return new Worker(new URL(scripts.worker, document.baseURI).href);
}

/** `PhysiN.Scene`: the adapter's scene, its thread taken from `PhysiN.scripts.worker`. */
export class Scene extends ModuleScene {
  constructor(options: SceneOptions = {}) {
    super({ ...options, worker: options.worker ?? chooseWorker() });
  }
}
