// The multi-DOF elements' channels grouped for the console's views (core/output/
// ChannelGroups.h), on the channels of a two-actuator specimen (ElementChannels.h's order)
// and a numerical link2d twin: each basic DOF and each actuator in a group of its own with its
// channels in order, the per-element groups of every deformation, force, stroke and actuator
// force, an actuator named like a basic DOF kept apart from it, and each channel's role.

#include "core/output/ChannelGroups.h"

#include <QtTest>

using namespace hsmu;

namespace {

std::vector<ElementChannel> specimenChannels(const std::string& element,
                                             const std::vector<std::string>& actuators) {
    std::vector<ElementChannel> out;
    const char* units[3][2] = {{"m", "kN"}, {"m", "kN"}, {"rad", "kN m"}};
    int k = 0;
    for (const char* dof : {"axial", "shear", "rotation"}) {
        out.push_back({element, std::string(dof) + " commanded", units[k][0]});
        out.push_back({element, std::string(dof) + " deformation", units[k][0]});
        out.push_back({element, std::string(dof) + " force", units[k][1]});
        ++k;
    }
    for (const std::string& a : actuators) {
        out.push_back({element, a + " command", "m"});
        out.push_back({element, a + " stroke", "m"});
        out.push_back({element, a + " force", "kN"});
    }
    return out;
}

} // namespace

class TestChannelGroups : public QObject {
    Q_OBJECT
private slots:
    void specimenAndTwin() {
        std::vector<ElementChannel> channels =
            specimenChannels("Column L", {"vertical", "lateral"});
        for (const char* dof : {"axial", "shear", "rotation"}) {
            channels.push_back({"Column R", std::string(dof) + " deformation", "m"});
            channels.push_back({"Column R", std::string(dof) + " force", "kN"});
        }
        const std::vector<ChannelGroup> g = channelGroups(channels);
        // Column L: 3 DOFs, 2 actuators, 4 per-element groups; Column R: 3 DOFs, 2 groups
        QCOMPARE(int(g.size()), 3 + 2 + 4 + 3 + 2);
        QCOMPARE(g[0].kind, ChannelGroupKind::BasicDof);
        QCOMPARE(g[0].subject, std::string("axial"));
        QCOMPARE(g[0].channels, (std::vector<int>{0, 1, 2}));
        QCOMPARE(g[2].subject, std::string("rotation"));
        QCOMPARE(g[3].kind, ChannelGroupKind::Actuator);
        QCOMPARE(g[3].subject, std::string("vertical"));
        QCOMPARE(g[3].channels, (std::vector<int>{9, 10, 11}));
        QCOMPARE(g[4].subject, std::string("lateral"));
        QCOMPARE(g[4].channels, (std::vector<int>{12, 13, 14}));
        QCOMPARE(g[5].kind, ChannelGroupKind::Deformations);
        QCOMPARE(g[5].channels, (std::vector<int>{1, 4, 7}));
        QCOMPARE(g[6].kind, ChannelGroupKind::Forces);
        QCOMPARE(g[6].channels, (std::vector<int>{2, 5, 8}));
        QCOMPARE(g[7].kind, ChannelGroupKind::Strokes);
        QCOMPARE(g[7].channels, (std::vector<int>{10, 13}));
        QCOMPARE(g[8].kind, ChannelGroupKind::ActuatorForces);
        QCOMPARE(g[8].channels, (std::vector<int>{11, 14}));
        QCOMPARE(g[9].element, std::string("Column R"));
        QCOMPARE(g[9].channels, (std::vector<int>{15, 16}));
        QCOMPARE(g[12].kind, ChannelGroupKind::Deformations);
        QCOMPARE(g[13].channels, (std::vector<int>{16, 18, 20}));
        QCOMPARE(channelRole(channels[13], g[4]), std::string("stroke"));
        QCOMPARE(channelRole(channels[0], g[0]), std::string("commanded"));
        QCOMPARE(channelRole(channels[13], g[7]), std::string("lateral stroke"));
        QCOMPARE(channelGroupName(g[1]), std::string("Column L shear"));
        QCOMPARE(channelGroupName(g[4]), std::string("Column L actuator lateral"));
        QCOMPARE(channelGroupName(g[8]), std::string("Column L actuator forces"));
    }

    void actuatorNamedLikeADof() {
        const auto channels = specimenChannels("Brace", {"axial", "shear force"});
        const auto g = channelGroups(channels);
        QCOMPARE(g[3].kind, ChannelGroupKind::Actuator);
        QCOMPARE(g[3].subject, std::string("axial"));
        QCOMPARE(g[3].channels, (std::vector<int>{9, 10, 11}));
        QCOMPARE(g[0].channels, (std::vector<int>{0, 1, 2}));
        QCOMPARE(g[4].subject, std::string("shear force"));
        QCOMPARE(g[4].channels, (std::vector<int>{12, 13, 14}));
    }

    void deformationIndices() {
        const auto channels = specimenChannels("Column L", {"lateral"});
        QCOMPARE(basicDeformationChannels(channels, "Column L"), (std::array<int, 3>{1, 4, 7}));
        QCOMPARE(basicDeformationChannels(channels, "Column R"), (std::array<int, 3>{-1, -1, -1}));
    }

    void none() { QVERIFY(channelGroups({}).empty()); }
};

QTEST_APPLESS_MAIN(TestChannelGroups)
#include "TestChannelGroups.moc"
