/**
 * What every physics page shares: a renderer on the page's canvas, a camera with OrbitControls,
 * lights, a render loop that calls `scene.simulate`, a small stats read-out, and the test hook
 * `globalThis.physinDemo = { scene, frame }` (`frame` counts the frames whose report arrived).
 *
 * The thread comes from the URL: `?worker=1` steps the world in the package's worker, anything
 * else in the page's thread (the specification's default). `?frames=N` stops after N frames.
 */
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { Scene } from '@physin/three';

/** What the browser tests read. */
export interface DemoHook {
  scene: Scene;
  /** Frames whose report has been applied. */
  frame: number;
  /** Frames asked (simulate returned true). */
  asked: number;
  /** 'main' or 'worker'. */
  thread: 'main' | 'worker';
}

declare global {
  var physinDemo: DemoHook | undefined;
}

/** `?frames=N`: stop simulating after N frames (the browser tests compare threads that way). */
export function frameLimit(): number {
  const value = Number(new URLSearchParams(window.location.search).get('frames'));
  return Number.isInteger(value) && value > 0 ? value : Infinity;
}

/** True when the page was opened with `?worker=1`. */
export function wantsWorker(): boolean {
  return new URLSearchParams(window.location.search).get('worker') === '1';
}

/** This page's URL query with `changes` made (null removes a key), as an href. */
export function withQuery(changes: Record<string, string | null>): string {
  const next = new URLSearchParams(window.location.search);
  for (const [key, value] of Object.entries(changes)) {
    if (value === null) next.delete(key);
    else next.set(key, value);
  }
  const text = next.toString();
  return text === '' ? '?' : `?${text}`;
}

/**
 * Points the page's switch links at the other variant: `#switch-thread` between the page's thread
 * and the worker, and (when `dimensions` is given) `#switch-d` between 3D and 4D with its labels.
 */
export function linkSwitches(dimensions?: { readonly n: number; readonly to3: string; readonly to4: string }): void {
  const thread = document.getElementById('switch-thread') as HTMLAnchorElement | null;
  if (thread) {
    thread.href = withQuery({ worker: wantsWorker() ? null : '1' });
    thread.textContent = wantsWorker() ? 'Run in the main thread' : 'Run in a worker';
  }
  const d = document.getElementById('switch-d') as HTMLAnchorElement | null;
  if (d && dimensions) {
    d.href = withQuery({ d: dimensions.n === 4 ? null : '4' });
    d.textContent = dimensions.n === 4 ? dimensions.to3 : dimensions.to4;
  }
}

/** A small seeded generator (mulberry32), so a page's random scene is the same at every load. */
export function seeded(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Options of `startDemo`. */
export interface DemoOptions {
  /** The canvas to draw on. */
  readonly canvas: HTMLCanvasElement;
  /** Where the camera starts and what it looks at. */
  readonly eye?: readonly [number, number, number];
  readonly target?: readonly [number, number, number];
  /** The fixed frame time given to `simulate` (default 1/60 s, so runs are repeatable). */
  readonly frameTime?: number;
  /**
   * Called once per simulated frame, just before its `simulate`, with the number of frames asked
   * so far (the page's own per-frame work). Not called while a worker step is in flight, so a
   * scripted page runs the same in either thread however slow the worker is.
   */
  readonly beforeFrame?: (frame: number) => void;
  /** Called at every drawn frame, also while a worker step is in flight (draw timings). */
  readonly eachDraw?: () => void;
  /** Called after each report (read-outs). */
  readonly afterUpdate?: (frame: number) => void;
  /** An element to write "frame · ms" figures into. */
  readonly stats?: HTMLElement | null;
}

/** The running page: its renderer, camera and controls, and a way to swap the scene. */
export interface Demo {
  readonly renderer: THREE.WebGLRenderer;
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  readonly hook: DemoHook;
  /** Replaces the scene (the old one is disposed) and resets the frame count. */
  setScene(scene: Scene): void;
  /** Pauses or resumes the simulation (drawing goes on). */
  paused: boolean;
}

/** Lights and a sky colour every page uses. */
export function dressScene(scene: THREE.Scene): void {
  scene.background = new THREE.Color(0xeef1f5);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8899aa, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 2.2);
  sun.position.set(6, 12, 8);
  scene.add(sun);
}

/** Starts the render loop on `scene`. */
export function startDemo(scene: Scene, options: DemoOptions): Demo {
  const renderer = new THREE.WebGLRenderer({ canvas: options.canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  const camera = new THREE.PerspectiveCamera(50, 1, 0.05, 500);
  const eye = options.eye ?? [8, 6, 10];
  const target = options.target ?? [0, 1, 0];
  camera.position.set(eye[0], eye[1], eye[2]);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.set(target[0], target[1], target[2]);
  controls.update();
  const frameTime = options.frameTime ?? 1 / 60;
  const hook: DemoHook = { scene, frame: 0, asked: 0, thread: scene.host.thread };
  globalThis.physinDemo = hook;
  let stepMs = 0;
  let last = performance.now();
  const onUpdate = (): void => {
    hook.frame += 1;
    stepMs = performance.now() - last;
    options.afterUpdate?.(hook.frame);
  };
  const demo: Demo = {
    renderer,
    camera,
    controls,
    hook,
    paused: false,
    setScene(next: Scene): void {
      hook.scene.removeEventListener('update', onUpdate);
      hook.scene.dispose();
      hook.scene = next;
      hook.frame = 0;
      hook.asked = 0;
      hook.thread = next.host.thread;
      next.addEventListener('update', onUpdate);
    },
  };
  scene.addEventListener('update', onUpdate);

  const resize = (): void => {
    const canvas = renderer.domElement;
    const width = canvas.clientWidth;
    const height = canvas.clientHeight;
    if (
      canvas.width !== Math.floor(width * renderer.getPixelRatio()) ||
      canvas.height !== Math.floor(height * renderer.getPixelRatio())
    ) {
      renderer.setSize(width, height, false);
      camera.aspect = width / Math.max(1, height);
      camera.updateProjectionMatrix();
    }
  };

  const limit = frameLimit();
  const loop = (): void => {
    requestAnimationFrame(loop);
    resize();
    options.eachDraw?.();
    if (!demo.paused && hook.asked < limit && !hook.scene.busy) {
      options.beforeFrame?.(hook.asked);
      last = performance.now();
      if (hook.scene.simulate(frameTime, 1)) hook.asked += 1;
    }
    controls.update();
    renderer.render(hook.scene, camera);
    if (options.stats) {
      options.stats.textContent = `${hook.scene.bodyCount} bodies · frame ${hook.frame} · ${hook.thread} thread · ${stepMs.toFixed(1)} ms a step`;
    }
  };
  loop();
  return demo;
}
