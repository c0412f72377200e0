#include "src/output/viewer3d.h"

#include <cctype>
#include <cstdlib>

#include "src/output/atomic_file.h"
#include "src/output/gltf.h"
#include "src/output/html_text.h"
#include "src/output/json.h"

namespace drape {

namespace {

// three.js's files a view needs, relative to ThreeJsFolder(), in the order they load.
const char* const kThreeJsFiles[] = {"three.min.js", "examples/js/loaders/GLTFLoader.js",
                                     "examples/js/controls/OrbitControls.js"};

// drape's viewer: drapeViewer(id) turns the element `id` (a canvas, a list of shapes, a list of
// fields and the shapes as JSON) into a view. Each shape is a drape.glb in base64; the fabric
// (the glTF node "fabric") is coloured by the chosen field from blue (its lowest value) to sand
// (its highest), as drape.glb's own COLOR_0 is by height. The page's console says
// "drape 3D view <id>: drawn <label>" once a shape is drawn; the element's data-drawn attribute
// names it and data-painted counts the canvas's pixels that are not the white background, and an
// error anywhere in the page is put in the body's data-script-error (what the browser test reads).
constexpr char kViewerScript[] = R"js(
window.addEventListener('error', function (event) {
  document.body.setAttribute('data-script-error', String(event.message));
});
window.drapeViewer = function (id) {
  var root = document.getElementById(id);
  var canvas = root.querySelector('canvas');
  var shapeList = root.querySelector('select.shape');
  var fieldList = root.querySelector('select.field');
  var legend = root.querySelector('.legend');
  var shapes = JSON.parse(root.querySelector('script.shapes').textContent);
  var renderer = new THREE.WebGLRenderer({canvas: canvas, antialias: true,
                                          preserveDrawingBuffer: true});
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(canvas.clientWidth, canvas.clientHeight, false);
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x606060, 0.45));
  var sun = new THREE.DirectionalLight(0xffffff, 0.9);
  sun.position.set(-1, 3, 2);
  scene.add(sun);
  var camera = new THREE.PerspectiveCamera(35, canvas.clientWidth / canvas.clientHeight,
                                           0.001, 1000);
  var controls = new THREE.OrbitControls(camera, canvas);
  var current = null, framed = false;
  var blue = [0.29, 0.53, 0.86], sand = [0.87, 0.75, 0.55];
  function render() { renderer.render(scene, camera); }
  controls.addEventListener('change', render);
  function bytes(text) {
    var s = atob(text), a = new Uint8Array(s.length);
    for (var i = 0; i < s.length; ++i) a[i] = s.charCodeAt(i);
    return a.buffer;
  }
  function colour(field) {
    var fabric = current && current.getObjectByName('fabric');
    if (!fabric) return;
    var units = current.userData.field_units || {};
    fabric.traverse(function (o) {
      var values = o.geometry && o.geometry.attributes['_' + field];
      var colours = o.geometry && o.geometry.attributes.color;
      if (!values || !colours) return;
      var low = Infinity, high = -Infinity, i, t;
      for (i = 0; i < values.count; ++i) {
        low = Math.min(low, values.getX(i));
        high = Math.max(high, values.getX(i));
      }
      for (i = 0; i < values.count; ++i) {
        t = high > low ? (values.getX(i) - low) / (high - low) : 0.5;
        colours.setXYZ(i, blue[0] + t * (sand[0] - blue[0]), blue[1] + t * (sand[1] - blue[1]),
                       blue[2] + t * (sand[2] - blue[2]));
      }
      colours.needsUpdate = true;
      var unit = units['_' + field.toUpperCase()] || '';
      legend.textContent = 'blue ' + low.toPrecision(3) + ' to sand ' + high.toPrecision(3) +
                           (unit && unit !== '1' ? ' ' + unit : '');
    });
    render();
  }
  function painted() {
    var gl = renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    var pixels = new Uint8Array(4 * w * h), count = 0;
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    for (var i = 0; i < pixels.length; i += 4) {
      if (pixels[i] < 245 || pixels[i + 1] < 245 || pixels[i + 2] < 245) ++count;
    }
    return count;
  }
  function frame() {
    var box = new THREE.Box3().setFromObject(current.getObjectByName('fabric') || current);
    var size = box.getSize(new THREE.Vector3()).length() || 1;
    var centre = box.getCenter(new THREE.Vector3());
    camera.position.copy(centre).add(new THREE.Vector3(0.45, 0.75, 0.75).multiplyScalar(1.05 * size));
    camera.near = size / 1000;
    camera.far = size * 100;
    camera.updateProjectionMatrix();
    controls.target.copy(centre);
    controls.update();
  }
  function show(k) {
    new THREE.GLTFLoader().parse(bytes(shapes[k].glb), '', function (gltf) {
      if (current) scene.remove(current);
      current = gltf.scene;
      scene.add(current);
      if (!framed) frame();
      framed = true;
      colour(fieldList.value);
      root.setAttribute('data-drawn', shapes[k].label);
      root.setAttribute('data-painted', painted());
      console.log('drape 3D view ' + id + ': drawn ' + shapes[k].label);
    }, function (error) {
      root.setAttribute('data-error', String(error));
      console.error('drape 3D view ' + id + ': ' + error);
    });
  }
  shapeList.onchange = function () { show(Number(shapeList.value)); };
  fieldList.onchange = function () { colour(fieldList.value); };
  show(0);
};
)js";

// Text put inside a <script> element: "</" written "<\/" so that nothing in it ends the element.
std::string ScriptSafe(const std::string& text) {
  std::string safe;
  safe.reserve(text.size());
  for (size_t k = 0; k < text.size(); ++k) {
    safe += text[k];
    if (text[k] == '<' && k + 1 < text.size() && text[k + 1] == '/') safe += '\\';
  }
  return safe;
}

// The <option>s of the field list: each field of drape.glb but _FIXED, by its attribute's name.
std::string FieldOptions() {
  std::string options;
  for (const GltfField& field : GltfFields()) {
    if (field.attribute == "_FIXED") continue;
    std::string name;
    for (char c : field.attribute.substr(1)) name += static_cast<char>(std::tolower(c));
    std::string words = name;
    for (char& c : words) c = c == '_' ? ' ' : c;
    options +=
        "<option value=\"" + name + "\">" + HtmlText(words) + " (" + field.unit + ")</option>";
  }
  return options;
}

}  // namespace

std::filesystem::path ThreeJsFolder() {
  const char* folder = std::getenv("DRAPE_THREE_JS_DIR");
  return folder && *folder ? std::filesystem::path(folder)
                           : std::filesystem::path("/usr/share/javascript/three");
}

std::string ViewerScripts(std::string* missing) {
  std::string scripts;
  for (const char* file : kThreeJsFiles) {
    const std::string text = ReadWholeFile(ThreeJsFolder() / file);
    if (text.empty()) {  // none of three.js's files is empty
      *missing = "three.js not found: cannot read " + (ThreeJsFolder() / file).string() +
                 " (Debian's libjs-three; or set DRAPE_THREE_JS_DIR)";
      return "";
    }
    scripts += ScriptSafe(text) + "\n";
  }
  return "<script>\n" + scripts + kViewerScript + "</script>\n";
}

std::string ViewerHtml(const std::vector<ViewerShape>& shapes, const std::filesystem::path& folder,
                       int index) {
  std::vector<std::string> embedded;
  std::string options;
  for (const ViewerShape& shape : shapes) {
    if (embedded.size() == kViewerMaxShapes) break;
    const std::string glb = ReadWholeFile(folder / shape.file);
    if (glb.empty()) continue;  // unreadable (a drape.glb is never empty)
    options += "<option value=\"" + std::to_string(embedded.size()) + "\">" +
               HtmlText(shape.label) + "</option>";
    embedded.push_back(
        JsonInlineObject({{"label", JsonString(shape.label)}, {"glb", JsonString(Base64(glb))}}));
  }
  if (embedded.empty()) return "<p>3D view not drawn: no drape.glb could be read.</p>\n";
  const std::string id = "drape-view-" + std::to_string(index);
  const std::string more = shapes.size() > kViewerMaxShapes
                               ? " (the first " + std::to_string(kViewerMaxShapes) + " of " +
                                     std::to_string(shapes.size()) +
                                     " shapes; every drape.glb is in its folder)"
                               : "";
  return "<div class=\"drape-view\" id=\"" + id +
         "\"><canvas style=\"width:100%;height:520px;border:1px solid #bbb;touch-action:none\">"
         "</canvas><div>shape <select class=\"shape\">" +
         options + "</select> colour by <select class=\"field\">" + FieldOptions() + "</select>" +
         HtmlText(more) +
         " <span class=\"legend\"></span> · drag to turn, scroll to zoom, right-drag to "
         "move</div><script type=\"application/json\" class=\"shapes\">" +
         ScriptSafe(JsonList(embedded)) + "</script><script>drapeViewer('" + id +
         "');</script></div>\n";
}

}  // namespace drape
