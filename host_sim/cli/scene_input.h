// Scenes for the commands that take one: a projected `.edges` file as it is, or a Wavefront
// `.obj` model projected with the view (core/view: the README's convention, fixed point).
#pragma once
#include <string>
#include <vector>

#include "cli/options.h"
#include "haloplot/geometry/contract.h"
#include "haloplot/job/job.h"
#include "haloplot/view/projection.h"
#include "io/obj_file.h"
#include "pipeline/mesh_repair.h"
#include "pipeline/solid_pipeline.h"
#include "pipeline/triangulate.h"

namespace haloplot::host {

// The options every scene-taking command accepts (valued): --view AZ,EL (degrees, up to three
// decimals; default 30,40), --perspective D (world units after the OBJ's scaling to 2^19;
// default orthographic), --dump-edges FILE (the projected scene, in the order all outputs use).
// --up x|y|z|-x|-y|-z: the file's up axis (default z for STL, y for OBJ and PLY:
// with_model_defaults). --substep S: fit the projected scene in units of 2^-S steps
// (core/include/haloplot/view/projection.h). --weld EPS|off: weld a model's vertices within EPS
// (its file's units; 0: at the same position) or not (pipeline/mesh_repair.h); the default welds
// corners within the file's rounding of each other (weld_distance). --crease DEG|exact|off: edges
// between faces within DEG degrees, or flat but for the file's rounding, are drawn only as
// contours (default 0: flat but for the rounding; exact: exactly coplanar only).
// A camera instead of --view/--perspective: --eye X,Y,Z --look-at X,Y,Z (the model file's
// coordinates) look along the eye-to-look-at direction (orthographic); --fov DEG makes it a
// perspective camera (see aim_view). --roll DEG turns the picture counterclockwise about the
// view axis (with --view or a camera).
extern const char* const kSceneOptions[11];

// The options with the model file's own defaults filled in where not given: --up z for an STL
// (3-D printing's convention), y for the rest. Every use of a model's options goes through it,
// so `plot X.stl` is `plot X.stl --up z` in every output (the --dump-edges header says it).
Options with_model_defaults(const Options& o, const std::string& path);

// --up from the options (default y); false with *error naming the value.
bool parse_up(const Options& o, UpAxis* up, std::string* error);

// --fov in degrees, (0, 170] (0 when not given); false with *error naming the value.
bool camera_fov(const Options& o, double* deg, std::string* error);

// The view applied to the model where the core's View cannot say it, after read_model and
// before scale_view: with --fov, the model moved so the look-at point is the world origin
// (whole world units) and view->perspective = ceil(R / sin(fov / 2)), R the farthest vertex
// from that point in world units (the eye backs off until the bounding sphere fills the field
// of view; the page fit then sets the size); with --roll, the model turned about the view
// axis through the origin, in doubles, each coordinate rounded to whole world units (at most
// 1/2 unit each, under 1/30 step at the default page). False with *error if the model then
// leaves the world's range.
struct ObjModel;
bool aim_view(const Options& o, ObjModel* model, View* view, std::string* error);

// A model file (.obj, .stl, .ply) read and cleaned as every command draws it: welded
// (--weld), each shell oriented, coplanar edges dropped (--crease), turned Z-up (--up).
// *repair (may be null) says what the cleaning did.
bool read_model(const Options& o, const std::string& path, ObjModel* model, RepairReport* repair,
                std::string* error);

// Loads and, for OBJ, projects. On failure *error is a complete message (file:line: reason,
// or the option or projection problem).
// --view and --perspective into a View, its plot area the page's drawable area (--page,
// --landscape, --margin, --steps-per-mm: export/page.h); false with *error saying what is
// wrong.
bool parse_view(const Options& o, View* out, std::string* error);

// *substep_bits (may be null): the edges' units, 2^-S steps (an OBJ's view; an .edges file's
// '# substep S' header).
// --scale S (mm on paper per unit of the model file): the view's plot area shrunk so the
// fit draws the model at that scale; an error if it then leaves the page's drawable area.
// Nothing without --scale.
struct ObjModel;
bool scale_view(const Options& o, const ObjModel& model, View* view, std::string* error);

bool load_scene(const Options& o, const std::string& path, std::vector<Edge3>* edges,
                std::string* error, int32_t* substep_bits = nullptr);

// The model's facing of each triangle (view/facing.h) into scene->facing when the scene is in
// sub-step units; in whole steps the projected geometry is too coarse to agree with it (the
// QI would find conflicts on fine meshes), so the facing stays the projected area's (empty).
bool model_facing_of(const View& view, const std::vector<Point3>& world, SolidScene* scene,
                     std::string* error);

struct JobFile;
struct SolidOptions;
// A job's hidden-line settings (its view, dash in mm at its steps-per-mm, method, outline).
bool job_solid_settings(const JobFile& jf, SolidOptions* so, View* view, std::string* error);

// The scene a .job file names, as the edges its job draws: an .edges file as it is; an .obj
// model projected with the job's view; for the hidden-line drawings, the strokes of that mode
// (visible pieces, dashes, and the outline pass redrawn last), decided on the host and rounded
// to steps, layer after layer. *substep_bits (may be null): the edges' units (0 for the
// strokes). *layers (may be null): the strokes' layers (JobSpec::layers), none for the others.
bool load_job_scene(const JobFile& jf, std::vector<Edge3>* edges, std::string* error,
                    int32_t* substep_bits = nullptr, LayerCounts* layers = nullptr);
// The hidden-line settings of a job's solid options (method, outline, dash, hatching).
HiddenJob hidden_job(const SolidOptions& so);
// A hidden-line job's model itself (its view applied) and its settings, for a plot in bands.
bool load_solid_job_scene(const JobFile& jf, SolidScene* scene, HiddenJob* hidden,
                          std::string* error);

struct ObjModel;
// The refusal of a face whose boundary crosses itself (TriangulateStats::first_not_simple):
// "FILE:LINE: this face's boundary crosses itself: ...".
std::string not_simple_message(const std::string& path, const ObjModel& model,
                               const TriangulateStats& stats);

// An OBJ model with its faces for the hidden-line modes: projected vertices, the drawn edges
// (in the order every output uses) and the polygons split into triangles.
bool load_solid_scene(const Options& o, const std::string& path, SolidScene* scene,
                      TriangulateStats* stats, std::string* error);

// scene.repair_note, if any, on stderr (a line or two, each "haloplot: FILE: ..."): the
// shells that are not closed solids (cli/shells_note.h), the --crease hint.
void say_repair_note(const SolidScene& scene);

}  // namespace haloplot::host
