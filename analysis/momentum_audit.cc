// Momentum audit: JSON form and the warning of a balance that does not close.
#include "analysis/momentum_audit.h"

#include <sstream>

namespace vulnus::analysis
{
namespace
{
nlohmann::json vector_json(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }
} // namespace

nlohmann::json momentum_audit_json(const MomentumAudit& audit)
{
  return {{"initial_kg_m_s", vector_json(audit.initial)},
          {"bodies_now_kg_m_s", vector_json(audit.now)},
          {"removed_kg_m_s", vector_json(audit.removed)},
          {"support_impulse_N_s", vector_json(audit.supports)},
          {"external_impulse_N_s", vector_json(audit.external)},
          {"added_kg_m_s", vector_json(audit.added)},
          {"imbalance_kg_m_s", vector_json(audit.imbalance())},
          {"scale_kg_m_s", audit.scale()},
          {"relative_imbalance", audit.relative_imbalance()},
          {"tolerance", MomentumAudit::tolerance},
          {"closes", audit.closes()}};
}

std::optional<std::string> momentum_audit_warning(const nlohmann::json& summary)
{
  const auto audit = summary.find("momentum_audit");
  if (audit == summary.end() || !audit->is_object() || audit->value("closes", true))
    return std::nullopt;
  std::ostringstream o;
  o << "*** the momentum balance does not close: bodies now + removed - (initial + supports + "
       "external) = "
    << (*audit)["imbalance_kg_m_s"].dump() << " kg m/s, "
    << (*audit)["relative_imbalance"].get<double>() << " of the momentum that flowed ("
    << (*audit)["scale_kg_m_s"].get<double>() << " kg m/s; tolerance "
    << MomentumAudit::tolerance
    << "): a support, contact or coupling impulse is not accounted for, and the support "
       "reactions and target momentum of this run are not to be trusted";
  return o.str();
}
} // namespace vulnus::analysis
