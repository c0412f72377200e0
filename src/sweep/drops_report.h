// The drape-test report of repeated drops, OUT/report.html: one self-contained page (its pictures
// are inline SVG) with the overlaid shadow outlines of the drops over the disc and the flat
// specimen, the histograms of the drape coefficient and of the fold count, the radial profiles
// r(θ), the table of drops, the test and the fabric (SI), and the standard's specimen-size advice
// where the drape coefficient calls for another diameter.
#ifndef DRAPE_SRC_SWEEP_DROPS_REPORT_H_
#define DRAPE_SRC_SWEEP_DROPS_REPORT_H_

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include "src/output/provenance.h"
#include "src/scene/scene.h"
#include "src/sweep/drops.h"

namespace drape {

// BS 5058 / ISO 9073-9: a fabric tested with the 30 cm specimen whose drape coefficient is below
// 0.30 is tested again at 24 cm, above 0.85 at 36 cm. The advice for a test of
// `specimen_diameter` (m) with mean drape coefficient `dc`, or nothing.
std::optional<std::string> SpecimenSizeAdvice(double specimen_diameter, double dc);

// report.html: the statistics, figures and table of a drops run, the 3D view of the drops whose
// folders under `directory` (the report's own) hold a drape.glb, `provenance` at its foot.
void WriteDropsReport(const Scene& scene, const DropsSummary& summary, const Provenance& provenance,
                      std::ostream& html, const std::filesystem::path& directory = {});

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_DROPS_REPORT_H_
