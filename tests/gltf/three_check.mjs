// three.js (npm three: GLTFLoader and AnimationMixer, the way a web page plays a .glb) against
// animkit's own files, under Node:
//   cloth GLB PC2: the sheet's vertices at the first, middle and last frames, morph targets
//     applied as three.js applies them, match the point cache within 1e-5 m;
//   skeleton GLB BVH SCALE: every joint's world position at the first, middle and last frames
//     matches three.js's BVHLoader on the BVH (times SCALE, metres per file unit) within 1e-5 m.
// Exits 1 on a mismatch.
import fs from 'node:fs';
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { BVHLoader } from 'three/examples/jsm/loaders/BVHLoader.js';

const kTolerance = 1e-5;

function loadGlb(path) {
  const bytes = fs.readFileSync(path);
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

// POINTCACHE2: char[12], int32 version, int32 points, float32 start, float32 rate, int32
// samples, then samples x points x 3 float32.
function readPc2(path) {
  const b = fs.readFileSync(path);
  const view = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const points = view.getInt32(16, true), samples = view.getInt32(28, true);
  const frames = [];
  for (let s = 0; s < samples; ++s) {
    frames.push(new Float32Array(b.buffer.slice(b.byteOffset + 32 + s * points * 12,
                                                b.byteOffset + 32 + (s + 1) * points * 12)));
  }
  return frames;
}

function sampledFrames(count) {
  return [...new Set([0, Math.floor((count - 1) / 2), count - 1])];
}

// Plays a clip once and holds its last frame (looping would wrap its last keyframe's time
// back to the first frame).
function playOnce(mixer, clip) {
  const action = mixer.clipAction(clip);
  action.setLoop(THREE.LoopOnce);
  action.clampWhenFinished = true;
  action.play();
}

let worst = 0, mismatches = 0;
function compare(what, got, want) {
  const d = got.distanceTo(want);
  worst = Math.max(worst, d);
  if (!(d <= kTolerance)) {
    if (++mismatches <= 10) {
      console.log(`${what}: three.js ${got.toArray()} against ${want.toArray()} (${d} m apart)`);
    }
    process.exitCode = 1;
  }
}

async function checkCloth(glbPath, pc2Path) {
  const gltf = await loadGlb(glbPath);
  const frames = readPc2(pc2Path);
  const mesh = gltf.scene.getObjectByName('cloth');
  const mixer = new THREE.AnimationMixer(gltf.scene);
  playOnce(mixer, gltf.animations[0]);
  const times = gltf.animations[0].tracks.find((t) => t.name.endsWith('morphTargetInfluences')).times;
  const geometry = mesh.geometry;
  const base = geometry.attributes.position;
  const targets = geometry.morphAttributes.position;
  if (times.length !== frames.length) {
    console.log(`cloth: ${times.length} keyframes, ${frames.length} cache frames`);
    process.exitCode = 1;
  }
  for (const f of sampledFrames(frames.length)) {
    mixer.setTime(times[f]);
    mesh.updateMatrixWorld(true);
    const influences = mesh.morphTargetInfluences;
    for (let v = 0; v < base.count; ++v) {
      const p = new THREE.Vector3().fromBufferAttribute(base, v);
      influences.forEach((w, t) => {
        if (w !== 0) p.addScaledVector(new THREE.Vector3().fromBufferAttribute(targets[t], v), w);
      });
      p.applyMatrix4(mesh.matrixWorld);
      const want = new THREE.Vector3(frames[f][3 * v], frames[f][3 * v + 1], frames[f][3 * v + 2]);
      compare(`cloth frame ${f} vertex ${v}`, p, want);
    }
  }
  console.log(`cloth: ${base.count} vertices, ${frames.length} frames; worst ${worst} m, ` +
              `${mismatches} mismatches`);
}

function worldPositions(root, names) {
  root.updateMatrixWorld(true);
  const out = new Map();
  root.traverse((o) => {
    if (names.has(o.name)) out.set(o.name, new THREE.Vector3().setFromMatrixPosition(o.matrixWorld));
  });
  return out;
}

async function checkSkeleton(glbPath, bvhPath, scale) {
  const gltf = await loadGlb(glbPath);
  const bvh = new BVHLoader().parse(fs.readFileSync(bvhPath, 'utf8'));
  const bvhRoot = new THREE.Group();
  bvhRoot.add(bvh.skeleton.bones[0]);
  bvhRoot.scale.setScalar(scale);
  const names = new Set(bvh.skeleton.bones.map((b) => b.name).filter((n) => n !== 'ENDSITE'));
  const gltfMixer = new THREE.AnimationMixer(gltf.scene);
  playOnce(gltfMixer, gltf.animations[0]);
  const bvhMixer = new THREE.AnimationMixer(bvh.skeleton.bones[0]);
  playOnce(bvhMixer, bvh.clip);
  const times = bvh.clip.tracks[0].times;
  let joints = 0;
  for (const f of sampledFrames(times.length)) {
    gltfMixer.setTime(times[f]);
    bvhMixer.setTime(times[f]);
    const got = worldPositions(gltf.scene, names);
    const want = worldPositions(bvhRoot, names);
    joints = want.size;
    for (const [name, p] of want) {
      if (!got.has(name)) {
        console.log(`joint ${name} is missing from ${glbPath}`);
        process.exitCode = 1;
        continue;
      }
      compare(`${name} at frame ${f}`, got.get(name), p);
    }
  }
  console.log(`skeleton: ${joints} joints, ${times.length} frames; worst ${worst} m, ` +
              `${mismatches} mismatches`);
}

const [kind, ...args] = process.argv.slice(2);
if (kind === 'cloth') await checkCloth(args[0], args[1]);
else if (kind === 'skeleton') await checkSkeleton(args[0], args[1], Number(args[2]));
else {
  console.log('usage: three_check.mjs cloth GLB PC2 | skeleton GLB BVH SCALE');
  process.exit(2);
}
