// Tests of the one CONFIG rule (core/config/PresetCatalog.h) that `hsmu run`, the console,
// hsmu-controller and hsmu.run share: a file, then a preset of the catalog, then the generated
// shear buildings, then a path; errors name the file or "preset <id>" and list the presets.
// The catalog here is two folders of NAME.json (presetFolders), one holding the shipped
// paper-condition-3 under another name.

#include "core/config/JsonCursor.h"
#include "core/config/PresetCatalog.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>

using namespace hsmu;

namespace {

const std::string kPresets = HSMU_SOURCE_DIR "/resources/presets";

void copyFile(const std::string& from, const std::string& to) {
    std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
}

void write(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

std::string errorOf(const std::string& name, const PresetCatalog& c) {
    try {
        loadConfigOrPreset(name, c);
    } catch (const ConfigError& e) {
        return e.what();
    }
    return {};
}

} // namespace

class TestPresetCatalog : public QObject {
    Q_OBJECT

private slots:
    void foldersListTheFirstFolderWithPresetsAndFindEachFile() {
        QTemporaryDir empty, a, b;
        const std::string A = a.path().toStdString(), B = b.path().toStdString();
        copyFile(kPresets + "/paper-condition-3.json", A + "/lab-frame.json");
        copyFile(kPresets + "/sdof-bouc-wen.json", B + "/only-in-b.json");
        const std::vector<std::string> folders{empty.path().toStdString() + "/missing", A, B};
        const PresetCatalog c = presetFolders(folders);
        QCOMPARE(c.ids(), std::vector<std::string>{"lab-frame"}); // A: the first with any
        QCOMPARE(presetFile("lab-frame", folders).value(), A + "/lab-frame.json");
        QCOMPARE(presetFile("only-in-b", folders).value(), B + "/only-in-b.json");
        QVERIFY(c.text("only-in-b").has_value()); // found in a later folder
        QVERIFY(!c.text("nothing").has_value());
        QVERIFY(!presetFile("a/lab-frame", folders).has_value()); // a path is no preset id
    }

    void theRuleTakesAFileThenAPresetThenAShearBuildingThenAPath() {
        QTemporaryDir a, cwd;
        const std::string A = a.path().toStdString();
        copyFile(kPresets + "/paper-condition-3.json", A + "/lab-frame.json");
        const PresetCatalog c = presetFolders({A});

        const TestConfig preset = loadConfigOrPreset("lab-frame", c);
        QCOMPARE(preset.sourcePath, std::string("preset lab-frame"));
        const TestConfig file = loadConfigOrPreset(kPresets + "/paper-condition-3.json", c);
        QCOMPARE(file.name, preset.name);
        QCOMPARE(file.raw, preset.raw); // the same document either way

        // an existing file of the preset's name wins over the preset
        const std::string local = cwd.path().toStdString() + "/lab-frame";
        copyFile(kPresets + "/sdof-bouc-wen.json", local);
        QVERIFY(loadConfigOrPreset(local, c).name != preset.name);

        const TestConfig building = loadConfigOrPreset("shear-building-3", c);
        QCOMPARE(building.sourcePath, std::string("preset shear-building-3"));
        QCOMPARE(int(building.elements.size()), 3);
    }

    void errorsNameTheFileOrThePresetAndListThePresets() {
        QTemporaryDir a;
        const std::string A = a.path().toStdString();
        copyFile(kPresets + "/paper-condition-3.json", A + "/lab-frame.json");
        write(A + "/broken.json", "{\"name\": ");
        const PresetCatalog c = presetFolders({A});

        const std::string unknown = errorOf("no-such-preset", c);
        QVERIFY2(unknown.starts_with("no-such-preset: neither a configuration file nor a preset "
                                     "(presets: broken, lab-frame, and the generated "
                                     "shear-building-<N>"),
                 unknown.c_str());
        const std::string broken = errorOf("broken", c);
        QVERIFY2(broken.starts_with("preset broken: "), broken.c_str());
        const std::string path = errorOf(A + "/missing.json", c);
        QVERIFY2(path.find(A + "/missing.json") != std::string::npos, path.c_str());
        const std::string json = errorOf("missing.json", c); // a .json name is a path
        QVERIFY2(json.find("missing.json") != std::string::npos &&
                     json.find("neither") == std::string::npos,
                 json.c_str());
    }
};

QTEST_APPLESS_MAIN(TestPresetCatalog)
#include "TestPresetCatalog.moc"
