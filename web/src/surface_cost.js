// What a surface costs to draw on a software renderer (SwiftShader, where
// every fragment pays for its whole shader), cut without changing a pixel:
//
// - A closed surface (a whole sphere or torus) seen from outside its
//   bounding sphere hides all of its back faces behind front ones, so they
//   are culled there (FrontSide, or BackSide where the mesh winds inwards);
//   from inside, both sides are drawn again, as the exporter's double-sided
//   material says. On berry that halves the ball view's time.
// - The ball's shadow falls only within the key light's shadow camera, a
//   prism of half-width w about the ball's centre along the light. three.js
//   compiles its shadow lookups into every lit material once the renderer
//   has a shadow map, and gates them by a uniform that a software renderer
//   evaluates both ways: so each frame the surface's triangles are split in
//   two, those the prism may meet (drawn with the lookups) and the rest
//   (drawn by a copy of the material compiled without them, as are the ball
//   and the path, which receive no shadow). Each triangle is drawn once, so
//   nothing else in the view changes.
import * as THREE from 'three';

// Positions closer than this share a vertex when edges are counted (the
// exporter repeats vertices along texture seams and poles).
const WELD = 1e-5;

// True where every edge of the (welded) triangle mesh is shared by exactly
// two triangles: a closed surface with no rim.
function isClosed(geometry) {
  const position = geometry.attributes.position, index = geometry.index;
  if (!index || index.count < 12) return false;
  const box = geometry.boundingBox ?? (geometry.computeBoundingBox(), geometry.boundingBox);
  const size = box.getSize(new THREE.Vector3()).length() || 1;
  const key = new Map(), weld = new Int32Array(position.count);
  for (let i = 0; i < position.count; ++i) {
    const k = [position.getX(i), position.getY(i), position.getZ(i)].map((c) => Math.round(c / (WELD * size))).join(',');
    if (!key.has(k)) key.set(k, key.size);
    weld[i] = key.get(k);
  }
  const edges = new Map();
  for (let t = 0; t < index.count; t += 3) {
    const v = [weld[index.getX(t)], weld[index.getX(t + 1)], weld[index.getX(t + 2)]];
    if (v[0] === v[1] || v[1] === v[2] || v[0] === v[2]) continue;  // a pole's degenerate triangle
    for (let e = 0; e < 3; ++e) {
      const a = v[e], b = v[(e + 1) % 3];
      const k = a < b ? a * 4294967296 + b : b * 4294967296 + a;
      edges.set(k, (edges.get(k) ?? 0) + 1);
    }
  }
  for (const uses of edges.values()) if (uses !== 2) return false;
  return edges.size > 0;
}

// +1 where the triangles wind counter-clockwise seen from outside (the
// enclosed volume is positive), −1 where they wind inwards.
function windingSign(geometry) {
  const p = geometry.attributes.position, index = geometry.index;
  const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
  let volume = 0;
  for (let t = 0; t < index.count; t += 3) {
    a.fromBufferAttribute(p, index.getX(t));
    b.fromBufferAttribute(p, index.getX(t + 1));
    c.fromBufferAttribute(p, index.getX(t + 2));
    volume += a.dot(b.cross(c));
  }
  return volume >= 0 ? 1 : -1;
}

const WITHOUT_SHADOW_LOOKUPS = 'rollspin-without-shadow-lookups';

// A copy of a lit material whose program has no shadow code (three.js
// defines USE_SHADOWMAP for every lit material once the renderer has a
// shadow map; undefining it in both stages drops the lookups and their
// varyings alike). Its shading is the original's with the shadow at 1.
export function withoutShadowLookups(material) {
  const copy = material.clone();
  copy.onBeforeCompile = (shader) => {
    shader.vertexShader = `#undef USE_SHADOWMAP\n${shader.vertexShader}`;
    shader.fragmentShader = `#undef USE_SHADOWMAP\n${shader.fragmentShader}`;
  };
  copy.customProgramCacheKey = () => WITHOUT_SHADOW_LOOKUPS;
  return copy;
}

export function hasShadowLookups(material) {
  return material.customProgramCacheKey() !== WITHOUT_SHADOW_LOOKUPS;
}

// A geometry sharing `geometry`'s vertices, with an index of its own that
// is rewritten each frame.
function dynamicPart(geometry) {
  const part = new THREE.BufferGeometry();
  for (const [name, attribute] of Object.entries(geometry.attributes)) part.setAttribute(name, attribute);
  const index = new THREE.BufferAttribute(new geometry.index.array.constructor(geometry.index.count), 1);
  index.setUsage(THREE.DynamicDrawUsage);
  part.setIndex(index);
  part.boundingSphere = geometry.boundingSphere ?? (geometry.computeBoundingSphere(), geometry.boundingSphere);
  part.boundingBox = geometry.boundingBox ?? (geometry.computeBoundingBox(), geometry.boundingBox);
  part.setDrawRange(0, 0);
  return part;
}

// A receiving mesh split in two each frame: the triangles the shadow
// prism may meet (a child mesh with the original material, receiving the
// shadow) and the rest (the mesh itself, now without shadow lookups).
class ShadowPatch {
  constructor(mesh) {
    this.source = mesh;
    const geometry = mesh.geometry;
    this.triangles = geometry.index.array.slice();
    this.mesh = new THREE.Mesh(dynamicPart(geometry), mesh.material);
    this.mesh.name = `${mesh.name}-shadow`;
    this.mesh.receiveShadow = true;
    this.mesh.layers.mask = mesh.layers.mask;
    this.mesh.userData.shadowPatch = true;
    mesh.add(this.mesh);
    mesh.geometry = dynamicPart(geometry);
    mesh.material = withoutShadowLookups(mesh.material);
    mesh.receiveShadow = false;
    this.write(this.triangles.length, 0);
    this.across = new Float32Array(2 * geometry.attributes.position.count);
  }

  // Keeps the triangles whose light-space bounds meet the prism of
  // half-width `reach` about `centre` along `direction` (world), with a
  // margin for the square's corners (√2).
  update(centre, direction, reach) {
    // (A frame that only turns the camera keeps the split it has.)
    const key = `${centre.x},${centre.y},${centre.z},${direction.x},${direction.y},${direction.z},${reach}`;
    if (key === this.lastKey) return;
    this.lastKey = key;
    const toLocal = this.source.matrixWorld.clone().invert();
    const c = centre.clone().applyMatrix4(toLocal);
    const d = direction.clone().transformDirection(toLocal);
    const e1 = new THREE.Vector3(), e2 = new THREE.Vector3();
    e1.copy(Math.abs(d.x) < 0.9 ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 1, 0)).cross(d).normalize();
    e2.crossVectors(d, e1);
    // (The prism's width in local units: the node's scale is uniform.)
    const scale = new THREE.Vector3().setFromMatrixScale(toLocal).x;
    const r = Math.SQRT2 * reach * scale;
    const p = this.mesh.geometry.attributes.position.array, across = this.across;
    for (let i = 0, j = 0; i < p.length; i += 3, j += 2) {
      const x = p[i] - c.x, y = p[i + 1] - c.y, z = p[i + 2] - c.z;
      across[j] = x * e1.x + y * e1.y + z * e1.z;
      across[j + 1] = x * e2.x + y * e2.y + z * e2.z;
    }
    const from = this.triangles, rest = this.source.geometry.index.array, patch = this.mesh.geometry.index.array;
    let restCount = 0, patchCount = 0;
    for (let t = 0; t < from.length; t += 3) {
      const a = 2 * from[t], b = 2 * from[t + 1], k = 2 * from[t + 2];
      const apart = Math.max(across[a], across[b], across[k]) < -r || Math.min(across[a], across[b], across[k]) > r
        || Math.max(across[a + 1], across[b + 1], across[k + 1]) < -r
        || Math.min(across[a + 1], across[b + 1], across[k + 1]) > r;
      const to = apart ? rest : patch, at = apart ? restCount : patchCount;
      to[at] = from[t];
      to[at + 1] = from[t + 1];
      to[at + 2] = from[t + 2];
      if (apart) restCount += 3;
      else patchCount += 3;
    }
    this.write(restCount, patchCount);
  }

  // Draws the first `restCount` indices of the rest and `patchCount` of the patch.
  write(restCount, patchCount) {
    if (restCount === this.triangles.length) this.source.geometry.index.array.set(this.triangles);
    for (const [geometry, count] of [[this.source.geometry, restCount], [this.mesh.geometry, patchCount]]) {
      geometry.setDrawRange(0, count);
      geometry.index.clearUpdateRanges();
      geometry.index.addUpdateRange(0, count);
      geometry.index.needsUpdate = true;
    }
  }
}

// The surface meshes of one node ("surface", "surface.1", …; those that
// receive the shadow are set to before this): their culling and their
// shadow patches.
export class SurfaceCost {
  constructor(node) {
    const meshes = [];
    node.traverse((o) => { if (o.isMesh && !o.userData.shadowPatch) meshes.push(o); });
    this.closed = meshes.filter((o) => isClosed(o.geometry)).map((o) => ({
      mesh: o,
      sphere: o.geometry.boundingSphere ?? (o.geometry.computeBoundingSphere(), o.geometry.boundingSphere),
      cull: windingSign(o.geometry) > 0 ? THREE.FrontSide : THREE.BackSide,
      doubleSided: o.material.side,
    }));
    this.patches = meshes.filter((o) => o.receiveShadow).map((o) => new ShadowPatch(o));
    this.enabled = true;  // false: every triangle with the lookups, closed meshes double-sided (to compare)
  }

  // Before a frame from `camera`: culls the closed meshes it is outside of.
  cull(camera) {
    const eye = camera.getWorldPosition(new THREE.Vector3()), sphere = new THREE.Sphere();
    for (const c of this.closed) {
      sphere.copy(c.sphere).applyMatrix4(c.mesh.matrixWorld);
      const side = !this.enabled || sphere.containsPoint(eye) ? c.doubleSided : c.cull;
      for (const m of [c.mesh.material, ...c.mesh.children.filter((k) => k.userData.shadowPatch).map((k) => k.material)]) {
        if (m.side === side) continue;
        m.side = side;
        m.needsUpdate = true;
      }
    }
  }

  // Where the ball is now: the triangles its shadow may fall on.
  shadowAt(centre, direction, reach) {
    for (const patch of this.patches) patch.update(centre, direction, this.enabled ? reach : Infinity);
  }
}
