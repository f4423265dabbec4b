#include "sph/PairWork.hpp"

#include "core/Error.hpp"

namespace hvi::sph {

void PairWork::layOut(const NeighbourList& list, std::size_t lanes) {
    const std::size_t slots = list.active.size();
    m_start.resize(slots + 1);
    m_start[0] = 0;
    for (std::size_t a = 0; a < slots; ++a) {
        const int32_t row = list.row[a];
        const auto listed = static_cast<std::size_t>(list.offset[row + 1] - list.offset[row]);
        const std::size_t room = (listed + lanes - 1) / lanes * lanes;
        m_start[a + 1] = m_start[a] + static_cast<int64_t>(room);
    }
    const auto entries = static_cast<std::size_t>(m_start[slots]);
    m_particle.assign(slots, -1);
    m_count.assign(slots, 0);
    m_hoop.assign(slots, 0.0);
    m_source.resize(entries);
    m_sign.resize(entries);
    m_gz.resize(entries);
    m_gr.resize(entries);
}

double PairWork::heating(std::size_t a, const std::vector<double>& vz,
                         const std::vector<double>& vr) const {
    const auto i = static_cast<std::size_t>(m_particle[a]);
    const double vzi = vz[i], vri = vr[i];
    const auto k0 = static_cast<std::size_t>(m_start[a]);
    const std::size_t k1 = k0 + static_cast<std::size_t>(m_count[a]);
    double rate = m_hoop[a] * vri;
    for (std::size_t k = k0; k < k1; ++k) {
        const auto j = static_cast<std::size_t>(m_source[k]);
        rate += m_gz[k] * (vzi - vz[j]) + m_gr[k] * (vri - m_sign[k] * vr[j]);
    }
    return rate;
}

void PairWork::save(io::CheckpointState& s, const std::string& prefix) const {
    s.ints[prefix + "particle"] = m_particle;
    s.ints[prefix + "count"] = m_count;
    s.doubles[prefix + "hoop"] = m_hoop;
    std::vector<int32_t> source;
    std::vector<double> sign, gz, gr;
    for (std::size_t a = 0; a < m_particle.size(); ++a) {
        const auto k0 = static_cast<std::size_t>(m_start[a]);
        for (std::size_t k = k0; k < k0 + static_cast<std::size_t>(m_count[a]); ++k) {
            source.push_back(m_source[k]);
            sign.push_back(m_sign[k]);
            gz.push_back(m_gz[k]);
            gr.push_back(m_gr[k]);
        }
    }
    s.ints[prefix + "source"] = std::move(source);
    s.doubles[prefix + "sign"] = std::move(sign);
    s.doubles[prefix + "gz"] = std::move(gz);
    s.doubles[prefix + "gr"] = std::move(gr);
}

void PairWork::restore(const io::CheckpointState& s, const std::string& prefix) {
    const auto ints = [&](const std::string& name) -> const std::vector<int32_t>& {
        const auto it = s.ints.find(prefix + name);
        if (it == s.ints.end()) {
            throw InputError("<checkpoint>", "/" + prefix + name, "missing",
                             "a checkpoint written by this version of hvi-run");
        }
        return it->second;
    };
    const auto doubles = [&](const std::string& name,
                             std::size_t size) -> const std::vector<double>& {
        const auto it = s.doubles.find(prefix + name);
        if (it == s.doubles.end() || it->second.size() != size) {
            throw InputError("<checkpoint>", "/" + prefix + name, "missing or wrong size",
                             "a checkpoint written by this version of hvi-run");
        }
        return it->second;
    };
    m_particle = ints("particle");
    m_count = ints("count");
    m_source = ints("source");
    if (m_count.size() != m_particle.size()) {
        throw InputError("<checkpoint>", "/" + prefix + "count", "wrong size",
                         "a checkpoint written by this version of hvi-run");
    }
    m_hoop = doubles("hoop", m_particle.size());
    m_sign = doubles("sign", m_source.size());
    m_gz = doubles("gz", m_source.size());
    m_gr = doubles("gr", m_source.size());
    m_start.assign(m_particle.size() + 1, 0);
    for (std::size_t a = 0; a < m_particle.size(); ++a) {
        m_start[a + 1] = m_start[a] + m_count[a];
    }
    if (static_cast<std::size_t>(m_start.back()) != m_source.size()) {
        throw InputError("<checkpoint>", "/" + prefix + "source", "wrong size",
                         "a checkpoint written by this version of hvi-run");
    }
}

} // namespace hvi::sph
