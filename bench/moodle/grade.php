<?php
// The student's grade of the activity, as Moodle's gradebook holds it (bench/moodle_lti.py).
// Usage: php grade.php COURSE INSTANCE USERID
define('CLI_SCRIPT', true);
require(__DIR__ . '/config.php');
require_once($CFG->libdir . '/gradelib.php');
[$script, $course, $instance, $user] = $argv;
$grades = grade_get_grades($course, 'mod', 'lti', $instance, $user);
$item = reset($grades->items);
$grade = $item ? $item->grades[$user] : null;
if (!$item) {  // an activity without a grade of its own: the line item the tool made for it
    $made = $DB->get_record('ltiservice_gradebookservices', ['ltilinkid' => $instance]);
    $item = $made ? grade_item::fetch(['id' => $made->gradeitemid]) : null;
    $grade = $item ? $item->get_grade($user, false) : null;
    $grade = $grade && $grade->finalgrade !== null ? (object) ['grade' => $grade->finalgrade] : null;
}
echo json_encode(['grade' => $grade ? $grade->grade : null, 'max' => $item ? $item->grademax : null,
                  'label' => $item ? ($item->itemname ?? null) : null]), "\n";
