// The 3D view: the robot as lit spheres (leaves red, the others blue, as on
// robozoo-render's zoo sheets), a ground with a grid every 0.5 m, the target
// marked by a ring and a pole, a camera that follows the robot and orbit
// controls (drag, wheel) to look around. World z is up.
import * as THREE from "three";
import { OrbitControls } from "/three/examples/jsm/controls/OrbitControls.js";

const LEAF = 0xd62c24, INNER = 0x2858cc, TARGET = 0xf0b020;

/// The ground: a grid every 0.5 m (and every 1 m, darker) on a plain colour, with the scene's fog.
function groundMaterial() {
  return new THREE.ShaderMaterial({
    uniforms: THREE.UniformsUtils.merge([THREE.UniformsLib.fog, {
      ground: { value: new THREE.Color(0xc9c6bf) },
      minor: { value: new THREE.Color(0x8f8c85) },
      major: { value: new THREE.Color(0x5f5d58) },
    }]),
    fog: true,
    extensions: { derivatives: true },
    // Pushed back in depth, so that the target's ring on it always wins.
    polygonOffset: true, polygonOffsetFactor: 2, polygonOffsetUnits: 2,
    vertexShader: `
      varying vec2 vWorld;
      #include <fog_pars_vertex>
      void main() {
        vWorld = (modelMatrix * vec4(position, 1.0)).xy;
        vec4 mvPosition = modelViewMatrix * vec4(position, 1.0);
        gl_Position = projectionMatrix * mvPosition;
        #include <fog_vertex>
      }`,
    fragmentShader: `
      uniform vec3 ground, minor, major;
      varying vec2 vWorld;
      #include <fog_pars_fragment>
      // Coverage (0..1) of lines of about one pixel at every multiple of
      // 'spacing' (m), fading to their mean where the cells shrink to a few pixels.
      float lines(float spacing, out float fade) {
        vec2 p = vWorld / spacing, w = fwidth(p);
        vec2 d = abs(fract(p - 0.5) - 0.5) / max(w, 1e-6);
        fade = smoothstep(0.15, 0.4, max(w.x, w.y));
        return mix(1.0 - min(min(d.x, d.y), 1.0), 0.5 * (w.x + w.y), fade);
      }
      void main() {
        float fadeMinor, fadeMajor;
        float a = lines(0.5, fadeMinor), b = lines(1.0, fadeMajor);
        vec3 c = mix(ground, minor, clamp(a, 0.0, 1.0) * 0.85);
        c = mix(c, major, clamp(b, 0.0, 1.0) * 0.85);
        gl_FragColor = vec4(c, 1.0);
        #include <fog_fragment>
      }`,
  });
}

/// The spheres: one camera-facing square per sphere, in which the fragment
/// shader traces the sphere itself (per-pixel normal, Lambert light, depth),
/// so that a sphere costs its pixels, not hundreds of triangles: with software
/// WebGL the triangles of 50 tessellated spheres cost more than the rest of
/// the frame. Per sphere (instanced): centre, radius, colour.
function sphereMaterial() {
  return new THREE.ShaderMaterial({
    uniforms: THREE.UniformsUtils.merge([THREE.UniformsLib.fog, {
      sky: { value: new THREE.Color() }, earth: { value: new THREE.Color() }, up: { value: new THREE.Vector3() },
      keyColor: { value: new THREE.Color() }, keyDir: { value: new THREE.Vector3() },
      fillColor: { value: new THREE.Color() }, fillDir: { value: new THREE.Vector3() },
    }]),
    fog: true,
    extensions: { fragDepth: true },
    vertexShader: `
      attribute vec3 center;
      attribute float radius;
      attribute vec3 color;
      varying vec3 vCenter, vPoint, vColor;
      varying float vRadius;
      void main() {
        vec3 c = (modelViewMatrix * vec4(center, 1.0)).xyz;
        // A square through the centre, square to the line of sight, just
        // covering the sphere's outline: r d / sqrt(d^2 - r^2) from the centre.
        float d = length(c);
        vec3 toEye = -c / d;
        vec3 side = normalize(cross(abs(toEye.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), toEye));
        vec3 top = cross(toEye, side);
        float size = radius * d / sqrt(max(d * d - radius * radius, 1e-6));
        vPoint = c + (position.x * side + position.y * top) * size;
        vCenter = c;
        vRadius = radius;
        vColor = color;
        gl_Position = projectionMatrix * vec4(vPoint, 1.0);
      }`,
    fragmentShader: `
      uniform mat4 projectionMatrix;
      uniform vec3 sky, earth, up, keyColor, keyDir, fillColor, fillDir;
      varying vec3 vCenter, vPoint, vColor;
      varying float vRadius;
      #ifdef USE_FOG
        uniform vec3 fogColor;
        uniform float fogNear, fogFar;
      #endif
      void main() {
        // The ray from the eye (the origin of view space) through this pixel.
        vec3 ray = normalize(vPoint);
        float b = dot(ray, vCenter);
        float h = b * b - dot(vCenter, vCenter) + vRadius * vRadius;
        if (h < 0.0) discard;
        vec3 p = ray * (b - sqrt(h));
        vec3 n = (p - vCenter) / vRadius;
        vec3 light = mix(earth, sky, 0.5 + 0.5 * dot(n, up)) + keyColor * max(dot(n, keyDir), 0.0) +
                     fillColor * max(dot(n, fillDir), 0.0);
        gl_FragColor = vec4(vColor * light, 1.0);
        vec4 clip = projectionMatrix * vec4(p, 1.0);
        gl_FragDepthEXT = 0.5 + 0.5 * clip.z / clip.w;
        #ifdef USE_FOG
          gl_FragColor.rgb = mix(gl_FragColor.rgb, fogColor, smoothstep(fogNear, fogFar, -p.z));
        #endif
      }`,
  });
}

export class Scene {
  constructor(container) {
    this.container = container;
    // No multisampling: with software WebGL (SwiftShader) it costs several times the frame.
    this.renderer = new THREE.WebGLRenderer({ antialias: false });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xe8ecf0);
    this.scene.fog = new THREE.Fog(0xe8ecf0, 15, 60);
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.1, 300);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(-1.0, -4.5, 2.0);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.target.set(0, 0, 0.3);
    this.controls.enableKeys = false;  // the arrow keys step the timeline
    this.controls.update();

    // The lights, for the spheres' shader (world z up): a sky and a ground
    // colour, a key light from above and a weak fill light.
    this.sphereMaterial = sphereMaterial();
    const u = this.sphereMaterial.uniforms;
    u.sky.value.set(0xdde8ff).multiplyScalar(0.6);
    u.earth.value.set(0x807a70).multiplyScalar(0.6);
    u.keyColor.value.set(0xffffff).multiplyScalar(0.7);
    u.fillColor.value.set(0xffffff).multiplyScalar(0.25);
    this.lightsWorld = { up: new THREE.Vector3(0, 0, 1), keyDir: new THREE.Vector3(-0.35, -0.55, 1.0).normalize(),
                         fillDir: new THREE.Vector3(0.6, 0.4, 0.35).normalize() };
    // The same lights for three.js's own lit mesh, the target's pole.
    this.scene.add(new THREE.HemisphereLight(0xdde8ff, 0x807a70, 0.6));
    const key = new THREE.DirectionalLight(0xffffff, 0.7);
    key.position.set(-0.35, -0.55, 1.0);
    this.scene.add(key);
    const fill = new THREE.DirectionalLight(0xffffff, 0.25);
    fill.position.set(0.6, 0.4, 0.35);
    this.scene.add(fill);

    // The ground and its grid in one shader: lines every 0.5 m and darker ones
    // every metre, computed per pixel from the world position (antialiased, and
    // faded into their mean colour where they would be closer than a pixel or
    // two). Grid lines as line primitives (GridHelper) vanish near the camera
    // in headless Chromium's software GL: SwiftShader drops a line with an end
    // behind the camera, as every long line passing beside it has.
    const ground = new THREE.Mesh(new THREE.PlaneBufferGeometry(400, 400), groundMaterial());
    ground.renderOrder = -1;            // drawn first: everything else stands on it
    this.scene.add(ground);
    this.target = new THREE.Group();
    const ring = new THREE.Mesh(new THREE.RingBufferGeometry(0.35, 0.5, 48),
                                new THREE.MeshBasicMaterial({ color: TARGET, side: THREE.DoubleSide }));
    ring.position.z = 0.004;
    this.target.add(ring);
    const pole = new THREE.Mesh(new THREE.CylinderBufferGeometry(0.03, 0.03, 1.0, 12),
                                new THREE.MeshLambertMaterial({ color: TARGET }));
    pole.rotation.x = Math.PI / 2;
    pole.position.z = 0.5;
    this.target.add(pole);
    this.scene.add(this.target);

    this.mesh = null;       // the robot's spheres
    this.radius = [];
    this.focus = null;      // followed point (smoothed)
    this.resize();
    window.addEventListener("resize", () => this.resize());
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth), h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  setTarget(t) { this.target.position.set(t[0], t[1], 0); }

  /// A robot: radius[i], leaf[i] (1: leaf) per sphere, start: its starting
  /// centres (x,y,z per sphere). Two instanced meshes, one per colour. The
  /// camera backs off to frame the robot (keeping the direction it looks in).
  setRobot(radius, leaf, start) {
    if (this.mesh) { this.scene.remove(this.mesh); this.mesh.geometry.dispose(); }
    this.radius = radius;
    const n0 = Math.max(1, radius.length);
    const g = new THREE.InstancedBufferGeometry();
    g.setIndex([0, 1, 2, 0, 2, 3]);
    g.setAttribute("position", new THREE.Float32BufferAttribute([-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0], 3));
    const colours = new Float32Array(3 * n0), leafColour = new THREE.Color(LEAF), innerColour = new THREE.Color(INNER);
    for (let i = 0; i < radius.length; i++) (leaf[i] ? leafColour : innerColour).toArray(colours, 3 * i);
    g.setAttribute("center", new THREE.InstancedBufferAttribute(new Float32Array(3 * n0), 3).setUsage(THREE.DynamicDrawUsage));
    g.setAttribute("radius", new THREE.InstancedBufferAttribute(Float32Array.from(radius.length ? radius : [0]), 1));
    g.setAttribute("color", new THREE.InstancedBufferAttribute(colours, 3));
    g.maxInstancedCount = radius.length;
    this.mesh = new THREE.Mesh(g, this.sphereMaterial);
    this.mesh.frustumCulled = false;
    this.scene.add(this.mesh);
    this.focus = null;
    let extent = 0.5;
    const n = radius.length;
    const c = [0, 1, 2].map((k) => { let m = 0; for (let i = 0; i < n; i++) m += start[3 * i + k] / n; return m; });
    for (let i = 0; i < n; i++)
      extent = Math.max(extent, Math.hypot(start[3 * i] - c[0], start[3 * i + 1] - c[1], start[3 * i + 2] - c[2]) + radius[i]);
    const view = this.camera.position.clone().sub(this.controls.target).normalize();
    this.camera.position.copy(this.controls.target).addScaledVector(view, 3.2 * extent / Math.tan(this.camera.fov * Math.PI / 360) / 2);
    this.place(start, start, 0);
  }

  /// Sphere centres (flat x,y,z per sphere), a + (b - a) * f. snap: the
  /// camera jumps onto the robot instead of following it (paused: still frames).
  place(a, b, f, snap = false) {
    const n = this.radius.length;
    if (a.length !== 3 * n || b.length !== 3 * n) return;
    let cx = 0, cy = 0, cz = 0, mass = 0;
    const centers = this.mesh.geometry.attributes.center;
    for (let i = 0; i < n; i++) {
      const x = a[3 * i] + (b[3 * i] - a[3 * i]) * f;
      const y = a[3 * i + 1] + (b[3 * i + 1] - a[3 * i + 1]) * f;
      const z = a[3 * i + 2] + (b[3 * i + 2] - a[3 * i + 2]) * f;
      centers.setXYZ(i, x, y, z);
      const r = this.radius[i], w = r * r * r;
      cx += w * x; cy += w * y; cz += w * z; mass += w;
    }
    centers.needsUpdate = true;
    if (snap) this.focus = null;
    if (mass > 0) this.follow(cx / mass, cy / mass, cz / mass);
  }

  /// Moves camera and orbit centre together towards the robot's centre of mass
  /// (a spring of about half a second), keeping the angle the user chose.
  follow(x, y, z) {
    const goal = new THREE.Vector3(x, y, Math.max(0.2, z));
    if (this.focus === null) {
      this.focus = goal.clone();
      const d = this.focus.clone().sub(this.controls.target);
      this.controls.target.add(d);
      this.camera.position.add(d);
      return;
    }
    const step = goal.sub(this.focus).multiplyScalar(0.08);
    this.focus.add(step);
    this.controls.target.add(step);
    this.camera.position.add(step);
  }

  render() {
    this.controls.update();
    this.camera.updateMatrixWorld();
    const u = this.sphereMaterial.uniforms, view = this.camera.matrixWorldInverse;
    for (const k of ["up", "keyDir", "fillDir"]) u[k].value.copy(this.lightsWorld[k]).transformDirection(view);
    this.renderer.render(this.scene, this.camera);
  }
}
