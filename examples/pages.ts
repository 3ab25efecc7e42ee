/**
 * The list of example pages: the one place to register a page. `vite.config.ts` builds one HTML
 * entry per item (`<dir>/index.html`) and the site's index page shows one card per item, in this
 * order. To add a page, add its folder and one entry here (see README.md).
 */

/** One page of the examples site. */
export interface ExamplePage {
  /** Folder under examples/ holding the page's index.html; also its URL path (`/<dir>/`). */
  readonly dir: string;
  /** Title on the card (and, by convention, the page's <h1>). */
  readonly title: string;
  /** One line on the card: what the page shows. */
  readonly summary: string;
  /** Other URL queries the browser tests open the page with (e.g. 'd=4'). */
  readonly variants?: readonly string[];
}

/** Every page, in the order of the index. */
export const pages: readonly ExamplePage[] = [
  {
    dir: 'sandbox',
    title: 'Sandbox, in 3D and 4D',
    summary:
      'Bodies that fall; in 4D each is shown by its cut with the flat w = sliceW, and a ruler of w intervals moves the flat.',
    variants: ['d=4'],
  },
  {
    dir: 'donuts',
    title: 'Two donuts make a chain link',
    summary: 'Two solid 4D tori: lift one in w, slide it along x, bring it back, and they are linked without a cut.',
  },
  {
    dir: 'shapes',
    title: 'Every shape touches every shape',
    summary:
      'A capsule pile, a dumbbell of three meshes whose events name the part, a hanging chain of tori, icosahedra through a sensor, boxes that pass through one another.',
  },
  {
    dir: 'plugin',
    title: 'The five steps',
    summary: "Physijs's interface in PhysiN: a stack of boxes, a ball thrown at it, an octahedron read from its geometry.",
  },
  {
    dir: 'joints',
    title: 'Joints',
    summary:
      'A pendulum, a whipping chain, a motorised door, a joint that breaks; in 4D a hinge that turns through w and a pin moved along it.',
    variants: ['d=4'],
  },
  {
    dir: 'stress',
    title: 'Stress: 1000 boxes',
    summary:
      'A pile of 1000 boxes, or 320 hypercubes in 4D, in this thread or in a worker: ms per step, main-thread ms per frame, awake bodies.',
    variants: ['d=4'],
  },
  {
    dir: 'trade',
    title: 'The trade: accuracy against cost',
    summary:
      'Run a stack, a chain, a 1000:1 chain or a 4D stack with your iterations, sub-steps and rate: error against time, and against cost.',
    variants: ['worker=1'],
  },
  {
    dir: 'rotors',
    title: 'Rotors that stay rotations',
    summary: 'A tesseract in a 4D double rotation: why normalising a rotor is not enough, and what rotorCorrect does.',
  },
];
