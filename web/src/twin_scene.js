// The two views of the renders, side by side: the ball on its surface (left)
// and the Bloch sphere with the spin and field arrows (right). Both draw one
// three.js scene, the glTF exporter's GLB (nodes `surface`, `ball`, `path`,
// `bloch`, `spin`, `field`), through two renderers and two cameras that see
// different layers. Nothing here solves: poses come from the Timeline.
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { SurfaceCost, hasShadowLookups, withoutShadowLookups } from './surface_cost.js';

const BALL_LAYER = 0;
const BLOCH_LAYER = 1;
const FIELD_OF_VIEW_DEG = 35;

// The GLB inside the page (base64) as bytes.
export function embeddedBytes(element) {
  const text = element.textContent.trim();
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

function parseGlb(buffer) {
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

// The three.js quaternion of a spinor [qw, qx, qy, qz] (the sign is irrelevant to a rotation).
function rotationOf(q) {
  return new THREE.Quaternion(q[1], q[2], q[3], q[0]).normalize();
}

// A camera and its orbit controls over one view's element.
class View {
  // viewDeg: [azimuth, elevation] of the eye as the renders take them (render.azimuth_deg, elevation_deg).
  constructor(element, layer, viewDeg) {
    this.element = element;
    this.viewDeg = viewDeg;
    this.renderer = new THREE.WebGLRenderer({ antialias: false, alpha: true, preserveDrawingBuffer: false });
    this.basePixelRatio = Math.min(window.devicePixelRatio || 1, 2);
    this.renderer.setPixelRatio(this.basePixelRatio);
    this.renderer.outputColorSpace = THREE.SRGBColorSpace;
    this.renderer.setClearColor(0x000000, 0);
    element.prepend(this.renderer.domElement);
    this.camera = new THREE.PerspectiveCamera(FIELD_OF_VIEW_DEG, 1, 0.01, 1000);
    this.camera.layers.set(layer);
    this.controls = new OrbitControls(this.camera, element);
    this.controls.enableDamping = false;
    this.home = { target: new THREE.Vector3(), distance: 1 };
  }

  // Aims at a bounding sphere from the renders' direction.
  frame(sphere) {
    this.home.target.copy(sphere.center);
    this.home.distance = (1.15 * sphere.radius) / Math.sin(THREE.MathUtils.degToRad(FIELD_OF_VIEW_DEG / 2));
    this.camera.near = this.home.distance / 100;
    this.camera.far = this.home.distance * 20;
    this.reset();
  }

  reset() {
    const [az, el] = this.viewDeg.map(THREE.MathUtils.degToRad);
    const d = this.home.distance;
    // The renders' eye direction (cos el cos az, cos el sin az, sin el) in the scene (z up)
    // is (x, z, −y) in glTF's y-up world.
    const offset = new THREE.Vector3(Math.cos(el) * Math.cos(az), Math.sin(el), -Math.cos(el) * Math.sin(az)).multiplyScalar(d);
    this.camera.position.copy(this.home.target).add(offset);
    this.controls.target.copy(this.home.target);
    this.camera.updateProjectionMatrix();
    this.controls.update();
  }

  // Turns the camera about its target (keyboard orbit), radians.
  orbit(azimuth, elevation) {
    const offset = this.camera.position.clone().sub(this.controls.target);
    const spherical = new THREE.Spherical().setFromVector3(offset);
    spherical.theta -= azimuth;
    spherical.phi = THREE.MathUtils.clamp(spherical.phi - elevation, 0.05, Math.PI - 0.05);
    this.camera.position.copy(this.controls.target).add(new THREE.Vector3().setFromSpherical(spherical));
    this.controls.update();
  }

  zoom(factor) {
    const offset = this.camera.position.clone().sub(this.controls.target).multiplyScalar(factor);
    this.camera.position.copy(this.controls.target).add(offset);
    this.controls.update();
  }

  resize() {
    const w = Math.max(1, this.element.clientWidth), h = Math.max(1, this.element.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  render(scene) {
    this.renderer.render(scene, this.camera);
  }
}

// The key light's direction (glTF's y up): from above, over the viewer's shoulder.
const KEY_DIRECTION = new THREE.Vector3(-0.45, 1.0, 0.7).normalize();
// The shadow map covers only the ball's own shadow: seen from a directional
// light, a ball of radius R shades a disc of radius R round its centre on
// whatever lies behind it, so a square of ±SHADOW_REACH R about the ball
// holds all of it at any surface's shape; 256 texels across it are R/85
// each, finer than a map over the whole scene, and only the surface's
// triangles that meet it do the shadow lookups (SurfaceCost).
const KEY_INTENSITY = 2.2;
const SHADOW_MAP_SIZE = 256;
const SHADOW_REACH = 1.5;

// Lit as the renders are: a key light that casts the ball's shadow on the surface, a soft sky fill.
function addLights(scene) {
  const sky = new THREE.HemisphereLight(0xdfe8f2, 0x5a554f, 1.1);
  const key = new THREE.DirectionalLight(0xffffff, KEY_INTENSITY);
  key.castShadow = true;
  key.shadow.mapSize.set(SHADOW_MAP_SIZE, SHADOW_MAP_SIZE);
  key.shadow.bias = -0.0005;
  for (const light of [sky, key, key.target]) {
    light.layers.enableAll();
    scene.add(light);
  }
  return key;
}

// The key light looks at the ball from its direction, from outside the ball
// view's bounding sphere (its depth range holds the whole scene); its shadow
// camera spans the ball's shadow, ±SHADOW_REACH R about its centre.
function aimKeyLight(key, sphere, ballCentre, ballRadius) {
  const r = sphere.radius, w = SHADOW_REACH * ballRadius;
  key.target.position.copy(ballCentre);
  key.position.copy(ballCentre).addScaledVector(KEY_DIRECTION, 2 * r + sphere.center.distanceTo(ballCentre));
  key.target.updateMatrixWorld();
  Object.assign(key.shadow.camera, { left: -w, right: w, top: w, bottom: -w, near: 0.01 * r, far: 4 * r + 2 * sphere.center.distanceTo(ballCentre) });
  key.shadow.camera.updateProjectionMatrix();
}

// The renders shade with Blinn–Phong: each material the exporter wrote with
// its Phong terms (extras.rollspin: specular, shininess) becomes three.js's
// Blinn–Phong material with them, the same highlights as the renders and
// much cheaper than PBR on a software renderer (SwiftShader).
// three.js normalises Blinn–Phong, (s/2 + 1)/(4π) · cosⁿ, and the key light
// is 2.2 bright; the renders' highlight is specular · cosⁿ under a unit
// light: this scale, over (s/2 + 1), gives the renders' peak.
const PHONG_SCALE = (4 * Math.PI) / KEY_INTENSITY;
function shadeAsTheRenders(root) {
  root.traverse((o) => {
    const phong = o.isMesh ? o.material.userData?.rollspin : null;
    if (!phong || !o.material.isMeshStandardMaterial) return;
    const m = o.material;
    const common = { name: m.name, color: m.color, map: m.map, transparent: m.transparent, opacity: m.opacity,
      side: m.side, depthWrite: m.depthWrite };
    // No highlight (the surface, the path): Lambert's diffuse term is
    // Phong's without the specular lobe, the same pixels for less work.
    o.material = phong.specular > 0
      ? new THREE.MeshPhongMaterial({ ...common, shininess: phong.shininess,
        specular: new THREE.Color().setScalar(phong.specular * PHONG_SCALE / (0.5 * phong.shininess + 1)) })
      : new THREE.MeshLambertMaterial(common);
    m.dispose();
  });
}

export class TwinScene {
  constructor(ballElement, blochElement, viewDeg) {
    this.scene = new THREE.Scene();
    this.keyLight = addLights(this.scene);
    this.ballView = new View(ballElement, BALL_LAYER, viewDeg);
    this.blochView = new View(blochElement, BLOCH_LAYER, viewDeg);
    this.ballView.renderer.shadowMap.enabled = true;
    this.ballView.renderer.shadowMap.type = THREE.PCFShadowMap;
    this.views = [this.ballView, this.blochView];
    this.renderScale = 1;
  }

  async load(buffer) {
    const gltf = await parseGlb(buffer);
    this.root = gltf.scene;
    this.scene.add(this.root);
    const node = (name) => this.root.getObjectByName(name) || null;
    this.nodes = { ball: node('ball'), bloch: node('bloch'), spin: node('spin'), field: node('field') };
    for (const [name, object] of Object.entries(this.nodes))
      if (!object) console.warn(`rollspin viewer: the GLB has no node "${name}"`);
    // The ball casts its shadow on the surface (the renders' shadow pass).
    if (this.nodes.ball) this.nodes.ball.traverse((o) => (o.castShadow = true));
    // One surface and path per surface the clip shows: "surface", "surface.1", …
    // (three.js drops the dot from node names: "surface1").
    this.surfaces = [];
    for (let k = 0; ; ++k) {
      const name = (base) => THREE.PropertyBinding.sanitizeNodeName(k === 0 ? base : `${base}.${k}`);
      const parts = [node(name('surface')), node(name('path'))].filter(Boolean);
      if (parts.length === 0 && k > 0) break;
      for (const part of parts) part.scale.set(1, 1, 1);  // the GLB's rest pose hides all but the first
      this.surfaces.push({ parts, sphere: null });
    }
    for (const { parts } of this.surfaces) parts[0]?.traverse((o) => (o.receiveShadow = true));
    // The Bloch sphere and its arrows: the right view's layer only.
    if (this.nodes.bloch) this.nodes.bloch.traverse((o) => o.layers.set(BLOCH_LAYER));
    for (const name of ['spin', 'field'])
      if (this.nodes[name]) this.nodes[name].traverse((o) => o.layers.set(BLOCH_LAYER));
    shadeAsTheRenders(this.root);
    // (After the materials are final: the shadow patches copy them.)
    for (const surface of this.surfaces) surface.cost = surface.parts[0] ? new SurfaceCost(surface.parts[0]) : null;
    // The ball and the paths receive no shadow: their programs need no lookups.
    this.root.traverse((o) => {
      if (o.isMesh && !o.receiveShadow && !o.userData.shadowPatch && !o.layers.isEnabled(BLOCH_LAYER) && hasShadowLookups(o.material))
        o.material = withoutShadowLookups(o.material);
    });
    this.frameViews();
  }

  // The ball view of each surface frames that surface with its path (and
  // anything else the GLB holds outside the Bloch sphere), as the renders
  // frame each surface's stretch.
  frameViews() {
    this.root.updateMatrixWorld(true);
    const others = new Set(this.surfaces.flatMap((x) => x.parts));
    const commonBox = new THREE.Box3();
    this.root.traverse((o) => {
      if (o.isMesh && !o.layers.isEnabled(BLOCH_LAYER) && o !== this.nodes.ball && !others.has(o) && !others.has(o.parent))
        commonBox.expandByObject(o);
    });
    this.surfaces.forEach((surface, k) => {
      const box = commonBox.clone();
      for (const part of surface.parts) box.expandByObject(part);
      if (k === 0 && this.nodes.ball) box.expandByObject(this.nodes.ball);  // where it rests at s = 0
      surface.sphere = box.getBoundingSphere(new THREE.Sphere());
    });
    this.shownSurface = -1;
    this.showSurface(0);
    const blochBox = new THREE.Box3();
    if (this.nodes.bloch) blochBox.setFromObject(this.nodes.bloch);
    else blochBox.setFromCenterAndSize(new THREE.Vector3(), new THREE.Vector3(2, 2, 2));
    this.blochView.frame(blochBox.getBoundingSphere(new THREE.Sphere()));
  }

  // Shows surface k alone and frames the ball view on it (a change of
  // surface resets the ball view, as the renders cut to the new one's camera).
  showSurface(k) {
    if (k === this.shownSurface || !this.surfaces[k]) return;
    this.surfaces.forEach((surface, i) => surface.parts.forEach((p) => (p.visible = i === k)));
    this.shownSurface = k;
    this.ballView.frame(this.surfaces[k].sphere);
  }

  // Looks at the ball view from a segment's angles where its camera keys
  // turn it (as the renders' storyboard moves its camera); the reader's own
  // orbit stays until the next such change.
  showViewDeg(deg) {
    if (!deg || (this.shownViewDeg && deg[0] === this.shownViewDeg[0] && deg[1] === this.shownViewDeg[1])) return;
    const first = !this.shownViewDeg;
    this.shownViewDeg = deg;
    if (first && deg[0] === this.ballView.viewDeg[0] && deg[1] === this.ballView.viewDeg[1]) return;
    this.ballView.viewDeg = deg;
    this.ballView.reset();
  }

  // Poses the ball (centre, rotation) and the arrows at arc length s, on its surface.
  pose(timeline, s) {
    this.showSurface(timeline.surface(s));
    this.showViewDeg(timeline.viewDeg(s));
    const q = rotationOf(timeline.quaternion(s));
    const { ball, spin, field } = this.nodes;
    if (ball) {
      ball.position.set(...timeline.ballCentre(s));
      ball.quaternion.copy(q);
      const centre = ball.getWorldPosition(new THREE.Vector3());
      aimKeyLight(this.keyLight, this.surfaces[this.shownSurface]?.sphere ?? new THREE.Sphere(), centre, timeline.ballRadius);
      this.surfaces[this.shownSurface]?.cost?.shadowAt(centre, KEY_DIRECTION, SHADOW_REACH * timeline.ballRadius);
    }
    // The exporter's arrows (src/export/gltf_export.hpp): "spin" points at X(0) and
    // turns by q(s); "field" points along +z and turns onto B(s)/|B(s)|.
    if (spin) spin.quaternion.copy(q);
    if (field) {
      const b = new THREE.Vector3(...timeline.field(s));
      if (b.lengthSq() > 0) field.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), b.normalize());
    }
  }

  // Where the ball and the Bloch sphere are on the page (CSS pixels): for
  // embedding pages that label them, and for the browser test.
  screenCentres() {
    const centreOf = (view, object, name) => {
      const p = object ? object.getWorldPosition(new THREE.Vector3()) : new THREE.Vector3();
      p.project(view.camera);
      const box = view.element.getBoundingClientRect();
      return { name, element: view.element.id,
        centre: [box.left + ((p.x + 1) / 2) * box.width, box.top + ((1 - p.y) / 2) * box.height] };
    };
    // (eye: the unit vector from the view's target to its camera, in the scene's z-up frame.)
    const eyeOf = (view) => {
      const d = view.camera.position.clone().sub(view.controls.target).normalize();
      return [d.x, -d.z, d.y];
    };
    return [{ ...centreOf(this.ballView, this.nodes.ball, 'ball'), eye: eyeOf(this.ballView) },
      { ...centreOf(this.blochView, this.nodes.bloch, 'bloch'), eye: eyeOf(this.blochView) }];
  }

  resize() {
    for (const v of this.views) v.resize();
  }

  // SurfaceCost's savings on (the default) or off, for the next pose.
  set cheapSurfaces(on) {
    for (const surface of this.surfaces ?? []) if (surface.cost) surface.cost.enabled = Boolean(on);
  }

  get cheapSurfaces() {
    return this.surfaces?.find((x) => x.cost)?.cost.enabled ?? true;
  }

  // The share of the device's pixels each view renders (1: all of them);
  // the canvases keep their size on the page (FramePacer).
  setRenderScale(scale) {
    this.renderScale = scale;
    for (const v of this.views) {
      v.renderer.setPixelRatio(v.basePixelRatio * scale);
      v.resize();
    }
  }

  render() {
    this.surfaces?.[this.shownSurface]?.cost?.cull(this.ballView.camera);
    for (const v of this.views) v.render(this.scene);
  }
}
