#include "comms/openfresco/OpenSeesTwinLaw.h"

#include "core/hysteresis/BoucWen.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace hsmu::comms::of {

namespace {

/// The parameters OpenSees' twin carries (the rest, uRef and fRef, are the console's scales).
const char* const kRemote[] = {"k0", "alpha", "n", "beta", "gamma", "A0",
                               "deltaA", "deltaNu", "deltaEta"};
constexpr std::size_t kMaxLine = 4096;

bool isRemote(const std::string& name)
{
    return std::find(std::begin(kRemote), std::end(kRemote), name) != std::end(kRemote);
}

/// The shortest text that reads back as exactly v.
std::string numberText(double v)
{
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

bool readNumber(const std::string& text, std::size_t& at, double& out)
{
    while (at < text.size() && text[at] == ' ')
        ++at;
    const auto r = std::from_chars(text.data() + at, text.data() + text.size(), out);
    if (r.ec != std::errc{})
        return false;
    at = static_cast<std::size_t>(r.ptr - text.data());
    return true;
}

} // namespace

std::string OpenSeesTwinLaw::supported(const std::string& lawName)
{
    if (lawName == "boucWen")
        return {};
    return "an OpenSees twin supports the boucWen law only (found " + lawName + ")";
}

OpenSeesTwinLaw::OpenSeesTwinLaw(std::string host, std::uint16_t port, std::string element,
                                 std::unique_ptr<HysteresisLaw> model, OpenSeesTwinOptions options)
    : m_host(std::move(host)), m_port(port), m_element(std::move(element)),
      m_model(std::move(model)), m_options(options), m_names(m_model->parameterNames()),
      m_sent(m_names.size(), std::numeric_limits<double>::quiet_NaN())
{
    readScales();
}

void OpenSeesTwinLaw::readScales()
{
    const int u = m_model->parameterIndex("uRef"), f = m_model->parameterIndex("fRef");
    m_uRef = u >= 0 ? m_model->parameterValue(u) : 1.0;
    m_fRef = f >= 0 ? m_model->parameterValue(f) : 1.0;
}

OpenSeesTwinLaw::~OpenSeesTwinLaw()
{
    if (!m_socket.isOpen())
        return;
    std::string error, answer;
    const std::string bye = m_outbox + "bye\n";
    if (m_socket.write(bye.data(), bye.size(), 1.0, error))
        m_socket.readLine(answer, kMaxLine, 2.0, error);
    m_socket.closeAfterPeer(2.0);
}

void OpenSeesTwinLaw::fail(std::string why)
{
    m_reason = "OpenSees twin at " + m_host + ":" + std::to_string(m_port) + ": " + std::move(why);
}

bool OpenSeesTwinLaw::request(const std::string& text, std::string& answer)
{
    std::string error;
    if (!m_socket.write(text.data(), text.size(), m_options.replyDeadline, error) ||
        !m_socket.readLine(answer, kMaxLine, m_options.replyDeadline, error)) {
        m_broken = true;
        fail(error + " (the twin's state lived in that OpenSees process: start the test again)");
        return false;
    }
    ++m_roundTrips;
    return true;
}

bool OpenSeesTwinLaw::ensureOpen()
{
    if (m_opened)
        return true;
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(m_options.connectTimeout));
    std::string error;
    for (;;) {
        const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
        if (m_socket.connect(m_host, m_port, std::max(left, 0.05), error))
            break;
        if (Clock::now() >= deadline) {
            m_broken = true;
            fail("cannot connect: " + error + " (is opensees hsmu_twin.tcl running?)");
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100)); // refused: not up yet
    }
    std::string answer;
    std::string name = m_element; // a Tcl list word: no braces, backslashes or line breaks
    for (char& c : name)
        if (c == '{' || c == '}' || c == '\\' || c == '\n' || c == '\r')
            c = '_';
    if (!request("hello hsmu-twin 1 {" + name + "}\n", answer))
        return false;
    if (answer.rfind("ok hsmu-twin 1", 0) != 0) {
        m_broken = true;
        fail("not an hsmu_twin.tcl helper (it answered '" + answer + "')");
        return false;
    }
    std::string twin = "twin " + m_model->lawName();
    for (std::size_t i = 0; i < m_names.size(); ++i) {
        if (!isRemote(m_names[i]))
            continue;
        m_sent[i] = m_model->parameterValue(static_cast<int>(i));
        twin += " " + m_names[i] + " " + numberText(m_sent[i]);
    }
    if (!request(twin + "\n", answer))
        return false;
    if (answer.rfind("ok twin", 0) != 0) {
        m_broken = true;
        fail("the twin was not built: " + answer);
        return false;
    }
    m_opened = true;
    return true;
}

int OpenSeesTwinLaw::subSteps(double u) const
{
    // The in-process law splits an increment longer than half a yield deformation into 2^k
    // equal parts (BoucWen.h); OpenSees runs as many equal steps, so both integrate the same map.
    const auto* bw = dynamic_cast<const BoucWen*>(m_model.get());
    if (!bw)
        return 1;
    const BoucWenParameters& p = bw->parameters();
    const BoucWenIncrement inc =
        BoucWen::integrateState(p, bw->committedState(), (u - bw->committedDeformation()) / p.uRef);
    return inc.status == LawStatus::Ok ? std::max(inc.subSteps, 1) : 1;
}

LawStatus OpenSeesTwinLaw::setTrialDeformation(double u)
{
    if (!std::isfinite(u))
        return LawStatus::InvalidInput;
    if (m_broken || !ensureOpen())
        return LawStatus::NoConvergence;
    m_model->setTrialDeformation(u); // the local copy (tangents, clone); its status is not ours
    const std::string text = m_outbox + "trial " + numberText(u / m_uRef) + " " +
                             std::to_string(subSteps(u)) + "\n";
    m_outbox.clear();
    std::string answer;
    if (!request(text, answer))
        return LawStatus::NoConvergence;
    double f = 0.0, x = 0.0;
    std::size_t at = 2;
    if (answer.rfind("ok ", 0) != 0 || !readNumber(answer, at, f) || !readNumber(answer, at, x) ||
        !std::isfinite(f)) {
        fail(answer.rfind("error ", 0) == 0 ? answer.substr(6) : "unexpected answer '" + answer + "'");
        m_uTrial = m_uCommitted;
        m_fTrial = m_fCommitted;
        return LawStatus::NoConvergence;
    }
    m_reason.clear();
    m_uTrial = u;
    m_fTrial = f * m_fRef;
    return LawStatus::Ok;
}

void OpenSeesTwinLaw::commit()
{
    m_model->commit();
    m_uCommitted = m_uTrial;
    m_fCommitted = m_fTrial;
    if (m_opened)
        m_outbox += "commit\n";
}

void OpenSeesTwinLaw::revert()
{
    m_model->revert();
    m_uTrial = m_uCommitted;
    m_fTrial = m_fCommitted;
    if (m_opened)
        m_outbox += "revert\n";
}

void OpenSeesTwinLaw::revertToStart()
{
    m_model->revertToStart();
    m_uTrial = m_fTrial = m_uCommitted = m_fCommitted = 0.0;
    if (m_opened)
        m_outbox += "restart\n";
}

void OpenSeesTwinLaw::queueChangedParameters()
{
    // As the in-process law: the committed state is kept, a pending trial is dropped and the
    // committed force is the new parameters' at that state. OpenSees evaluates it only at the
    // next trial, so it comes from the local copy (which equals OpenSees' law to ~1e-14).
    m_fCommitted = m_model->committedForce();
    m_uTrial = m_uCommitted;
    m_fTrial = m_fCommitted;
    readScales();
    if (!m_opened)
        return; // the opening sends the current values
    std::string line;
    for (std::size_t i = 0; i < m_names.size(); ++i) {
        if (!isRemote(m_names[i]))
            continue;
        const double v = m_model->parameterValue(static_cast<int>(i));
        if (v == m_sent[i])
            continue;
        line += " " + m_names[i] + " " + numberText(v);
        m_sent[i] = v;
    }
    if (!line.empty())
        m_outbox += "param" + line + "\n";
}

int OpenSeesTwinLaw::setParameterValues(std::span<const int> indices,
                                        std::span<const double> values, bool allOrNothing)
{
    const int refused = m_model->setParameterValues(indices, values, allOrNothing);
    queueChangedParameters();
    return refused;
}

} // namespace hsmu::comms::of
