#include "indentation/contact_terms.hpp"

#include "indentation/elastic_face.hpp"
#include "indentation/nodal_gaps.hpp"
#include "indentation/power_law_approach.hpp"
#include "indentation/thin_layer.hpp"
#include "indentation/weighted_gaps.hpp"

namespace si {
namespace {

std::unique_ptr<ContactRows> make_rows(const IndentationOptions& o, const ContactRowsSetting& s) {
  if (o.interpolated_traction) return std::make_unique<WeightedGaps>(s, o.interpolated);
  auto rows = std::make_unique<NodalGaps>(s);
  if (o.nodal_fbar) rows->set_fbar(*o.nodal_fbar, o.contact_offset);
  return rows;
}

}  // namespace

ContactParts make_contact_parts(const IndentationOptions& options,
                                const ContactRowsSetting& setting) {
  ContactParts parts;
  const std::vector<int>& frame_nodes = setting.shell.model().frame_nodes;
  if (!frame_nodes.empty()) {
    auto frame = std::make_unique<SupportFrame>(SupportFrameSetting{
        setting.shell, frame_nodes, options.frame_offset, setting.kappa, setting.ncp});
    parts.frame = frame.get();
    parts.terms.push_back(std::move(frame));
  }
  std::unique_ptr<ContactRows> rows = make_rows(options, setting);
  parts.indenter = rows.get();
  const double sym = setting.shell.model().symmetry_factor;
  std::unique_ptr<ContactTerm> law;
  if (options.local.kind == LocalLawKind::kPowerLaw) {
    auto power = std::make_unique<PowerLawApproach>(options.local, setting.body, *rows, sym);
    rows->set_approach(*power);
    law = std::move(power);
  } else if (options.local.kind == LocalLawKind::kThinLayer) {
    auto layer = std::make_unique<ThinLayer>(options.local.compliance, setting.shell, *rows);
    rows->set_approach(*layer);
    law = std::move(layer);
  } else if (options.local.kind == LocalLawKind::kElasticFace) {
    auto face = std::make_unique<ElasticFace>(options.local.face, setting.shell, setting.body,
                                              *rows, options.face_zone_bound);
    rows->set_approach(*face);
    law = std::move(face);
  }
  rows->set_candidates(setting.body.reachable());
  parts.terms.push_back(std::move(rows));
  if (law) parts.terms.push_back(std::move(law));
  return parts;
}

}  // namespace si
