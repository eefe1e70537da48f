// The same rig and clips as .glb and .fbx, played by three.js in node: GLTFLoader
// and FBXLoader parse the files (no browser, no DOM), an AnimationMixer plays
// every clip, and every joint's world position is sampled at 4x the key rate
// (each interval between two of the clip's key times cut in four). The two
// files must agree within TOLERANCE metres at every sample (issue 21 item 2).
// FBX positions are brought to metres with the file's UnitScaleFactor (cm);
// the loader itself turns a Z-up file to Y-up.
// --fbx-keys: the FBX clip's key times are merged in too (a cubic glTF clip
// has few keys; its FBX is keyed densely: each of those intervals is cut in four).
// --reference REF.json (rigsmith-cli build --reference): both files hold
// exactly the reference's clips, by name, each as long as it says.
// usage: node compare-three.mjs FILE.glb FILE.fbx [TOLERANCE=1e-4] [--fbx-keys] [--reference REF.json]
// Prints one line per clip and "CHECK three <worst>" on success; exits 1 on any
// disagreement or a missing clip, joint or track.
import { readFileSync } from 'node:fs';

// What the loaders touch outside parsing: FBXLoader's `window` (only for
// cameras) and GLTFLoader's `self.URL` (only for images). No DOM is needed.
globalThis.self ??= globalThis;
globalThis.window ??= { innerWidth: 1, innerHeight: 1 };

const THREE = await import('three');
const { GLTFLoader } = await import('three/examples/jsm/loaders/GLTFLoader.js');
const { FBXLoader } = await import('three/examples/jsm/loaders/FBXLoader.js');

const argv = process.argv.slice(2);
const fbxKeys = argv.includes('--fbx-keys');
const referenceAt = argv.indexOf('--reference');
const referencePath = referenceAt >= 0 ? argv[referenceAt + 1] : null;
const [glbPath, fbxPath, toleranceArg] = argv.filter((a, i) => a !== '--fbx-keys' && (referenceAt < 0 || (i !== referenceAt && i !== referenceAt + 1)));
if (!glbPath || !fbxPath) {
  console.error('usage: node compare-three.mjs FILE.glb FILE.fbx [TOLERANCE]');
  process.exit(2);
}
const tolerance = Number(toleranceArg ?? 1e-4);
// FBXLoader warns once per Z-up file: keep the output to what the check says.
console.warn = () => {};

function arrayBufferOf(path) {
  const bytes = readFileSync(path);
  return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
}

const gltf = await new Promise((resolve, reject) =>
  new GLTFLoader().parse(arrayBufferOf(glbPath), '', resolve, reject));
const fbxRoot = new FBXLoader().parse(arrayBufferOf(fbxPath), '');
const fbxScale = (fbxRoot.userData.unitScaleFactor ?? 100) / 100; // file units to metres

// The joints: every named glTF node that is not a mesh, found by name in the FBX.
const joints = [];
gltf.scene.traverse((o) => {
  if (o.isMesh || o === gltf.scene || !o.name) return;
  const other = fbxRoot.getObjectByName(o.name);
  if (!other) {
    console.error(`ERROR joint ${o.name} is missing from the FBX`);
    process.exit(1);
  }
  joints.push([o, other]);
});

// The clip's key times: every track's times, merged.
function keyTimes(clip, other) {
  const all = new Set();
  for (const c of other ? [clip, other] : [clip])
    for (const track of c.tracks) for (const t of track.times) all.add(Math.round(t * 1e6) / 1e6);
  return [...all].sort((a, b) => a - b);
}

function player(root, clip) {
  const mixer = new THREE.AnimationMixer(root);
  const action = mixer.clipAction(clip);
  action.setLoop(THREE.LoopOnce, 1);
  action.clampWhenFinished = true;
  action.play();
  return (time) => {
    mixer.setTime(time);
    root.updateMatrixWorld(true);
  };
}

if (gltf.animations.length === 0) {
  console.error('ERROR the glb has no clip');
  process.exit(1);
}
let worst = 0, samples = 0, failed = false;
const position = new THREE.Vector3(), other = new THREE.Vector3();
for (const clip of gltf.animations) {
  const fbxClip = fbxRoot.animations.find((c) => c.name === clip.name);
  if (!fbxClip) {
    console.error(`ERROR clip ${clip.name} is missing from the FBX`);
    failed = true;
    continue;
  }
  const times = keyTimes(clip, fbxKeys ? fbxClip : null);
  const playGltf = player(gltf.scene, clip), playFbx = player(fbxRoot, fbxClip);
  let clipWorst = 0, where = '', travel = 0;
  const rest = new Map();
  for (let k = 0; k + 1 < times.length; ++k) {
    for (let q = 0; q < 4 || (q === 4 && k + 2 === times.length); ++q) {
      const time = times[k] + (times[k + 1] - times[k]) * q / 4;
      playGltf(time);
      playFbx(time);
      for (const [a, b] of joints) {
        a.getWorldPosition(position);
        b.getWorldPosition(other).multiplyScalar(fbxScale);
        const d = position.distanceTo(other);
        if (!rest.has(a)) rest.set(a, position.clone());
        travel = Math.max(travel, position.distanceTo(rest.get(a)));
        if (d > clipWorst) {
          clipWorst = d;
          where = `${a.name} at ${time.toFixed(4)} s`;
        }
      }
      ++samples;
    }
  }
  console.log(`clip ${clip.name}: ${times.length} key times, ${joints.length} joints, ` +
    `joints travel up to ${travel.toFixed(3)} m, worst ${clipWorst.toExponential(2)} m (${where})`);
  if (travel < 1e-3) {
    console.error(`ERROR clip ${clip.name} moves no joint in three.js`);
    failed = true;
  }
  if (clipWorst > tolerance) {
    console.error(`ERROR clip ${clip.name}: glTF and FBX differ by ${clipWorst.toExponential(3)} m at ${where} (tolerance ${tolerance})`);
    failed = true;
  }
  worst = Math.max(worst, clipWorst);
}
for (const clip of fbxRoot.animations)
  if (!gltf.animations.find((c) => c.name === clip.name)) {
    console.error(`ERROR clip ${clip.name} is only in the FBX`);
    failed = true;
  }
if (referencePath) {
  const clips = JSON.parse(readFileSync(referencePath, 'utf8')).clips;
  for (const [kind, animations] of [['glTF', gltf.animations], ['FBX', fbxRoot.animations]]) {
    if (animations.length !== clips.length) {
      console.error(`ERROR the ${kind} has ${animations.length} clips, the reference ${clips.length}`);
      failed = true;
    }
    for (const clip of clips) {
      const found = animations.find((c) => c.name === clip.name);
      if (!found) {
        console.error(`ERROR clip ${clip.name} is missing from the ${kind}`);
        failed = true;
      } else if (Math.abs(found.duration - clip.seconds) > 1e-3) {
        console.error(`ERROR the ${kind}'s clip ${clip.name} lasts ${found.duration} s, the reference ${clip.seconds} s`);
        failed = true;
      }
    }
  }
  if (!failed) console.log(`clips named and timed as the reference: ${clips.map((c) => `${c.name} ${c.seconds.toFixed(3)} s`).join(', ')}`);
}
if (failed) process.exit(1);
console.log(`CHECK three ${gltf.animations.length} clips, ${samples} samples, worst ${worst.toExponential(2)} m`);
