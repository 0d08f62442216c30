#include "core/output/ChannelGroups.h"

namespace hsmu {

namespace {

bool endsWith(const std::string& s, const std::string& suffix, std::string& head) {
    if (s.size() <= suffix.size() + 1 ||
        s.compare(s.size() - suffix.size(), suffix.size(), suffix) != 0 ||
        s[s.size() - suffix.size() - 1] != ' ')
        return false;
    head = s.substr(0, s.size() - suffix.size() - 1);
    return true;
}

} // namespace

std::vector<ChannelGroup> channelGroups(const std::vector<ElementChannel>& channels) {
    std::vector<ChannelGroup> out;
    std::size_t i = 0;
    while (i < channels.size()) {
        const std::string element = channels[i].element;
        std::vector<ChannelGroup> own;
        ChannelGroup deformations{ChannelGroupKind::Deformations, element, "", {}};
        ChannelGroup forces{ChannelGroupKind::Forces, element, "", {}};
        ChannelGroup strokes{ChannelGroupKind::Strokes, element, "", {}};
        ChannelGroup actuatorForces{ChannelGroupKind::ActuatorForces, element, "", {}};
        for (; i < channels.size() && channels[i].element == element; ++i) {
            const std::string& name = channels[i].name;
            const int index = int(i);
            std::string head;
            ChannelGroupKind kind;
            if (endsWith(name, "commanded", head) || endsWith(name, "deformation", head))
                kind = ChannelGroupKind::BasicDof;
            else if (endsWith(name, "command", head) || endsWith(name, "stroke", head))
                kind = ChannelGroupKind::Actuator;
            else if (endsWith(name, "force", head) && !own.empty() && own.back().subject == head)
                kind = own.back().kind;
            else
                continue; // a channel of no known form: in the record, not in a group
            if (own.empty() || own.back().subject != head || own.back().kind != kind)
                own.push_back({kind, element, head, {}});
            own.back().channels.push_back(index);
            std::string rest;
            const bool isForce = endsWith(name, "force", rest);
            if (kind == ChannelGroupKind::BasicDof && isForce)
                forces.channels.push_back(index);
            else if (kind == ChannelGroupKind::BasicDof && endsWith(name, "deformation", rest))
                deformations.channels.push_back(index);
            else if (isForce)
                actuatorForces.channels.push_back(index);
            else if (endsWith(name, "stroke", rest))
                strokes.channels.push_back(index);
            // "<k> commanded" and "<a> command" are in their own group only
        }
        out.insert(out.end(), own.begin(), own.end());
        for (ChannelGroup* g : {&deformations, &forces, &strokes, &actuatorForces})
            if (!g->channels.empty())
                out.push_back(*g);
    }
    return out;
}

std::string channelRole(const ElementChannel& c, const ChannelGroup& g) {
    const std::string& s = c.name;
    if (!g.subject.empty() && s.size() > g.subject.size() + 1 &&
        s.compare(0, g.subject.size(), g.subject) == 0 && s[g.subject.size()] == ' ')
        return s.substr(g.subject.size() + 1);
    return s;
}

std::string channelGroupName(const ChannelGroup& g) {
    switch (g.kind) {
    case ChannelGroupKind::BasicDof:
        return g.element + " " + g.subject;
    case ChannelGroupKind::Actuator:
        return g.element + " actuator " + g.subject;
    case ChannelGroupKind::Deformations:
        return g.element + " deformations";
    case ChannelGroupKind::Forces:
        return g.element + " forces";
    case ChannelGroupKind::Strokes:
        return g.element + " strokes";
    case ChannelGroupKind::ActuatorForces:
        return g.element + " actuator forces";
    }
    return g.element;
}

std::array<int, 3> basicDeformationChannels(const std::vector<ElementChannel>& channels,
                                            const std::string& element) {
    std::array<int, 3> out{-1, -1, -1};
    const char* names[3] = {"axial deformation", "shear deformation", "rotation deformation"};
    for (std::size_t i = 0; i < channels.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (channels[i].element == element && channels[i].name == names[k])
                out[std::size_t(k)] = int(i);
    return out;
}

} // namespace hsmu
