#pragma once
// Which texture set to import from a folder holding several: a filter field over the list (a
// download of 65 sets is searched, not scrolled), each set with what its files are, and the sets
// whose files name no height, depth, bump or normal map marked: nothing in them gives relief, so
// the import would refuse them (unless a file's texels turn out to be a height map).

#include <QDialog>
#include <string>
#include <vector>

class QLineEdit;
class QListWidget;

namespace px::studio {

struct SetChoice {
    QString name;
    bool relief = true; // a file named as a height, depth, bump or normal map
    int files = 0;
};

// The sets among `files`, sorted, with whether their files' names promise relief.
std::vector<SetChoice> setChoices(const std::vector<std::string>& files);

class SetPickerDialog : public QDialog {
    Q_OBJECT
public:
    SetPickerDialog(const QString& source, const std::vector<SetChoice>& sets,
                    QWidget* parent = nullptr);

    QString chosen() const; // empty: none
    QLineEdit* filterField() const { return m_filter; }
    QListWidget* list() const { return m_list; }
    // The sets shown under the filter.
    QStringList shown() const;

private:
    void applyFilter(const QString& text);

    QLineEdit* m_filter;
    QListWidget* m_list;
};

} // namespace px::studio
