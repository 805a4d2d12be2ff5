<?php
// Sets up a Moodle (4.5) for bench/moodle_lti.py: the app registered as an LTI 1.3 tool
// (keyset URL, login and redirection URLs, deep linking, grades by AGS, no names or
// e-mails), a course with a teacher and a student, and one activity of the tool whose
// custom parameters name the task and method. Prints what the app must register, as JSON.
// Usage: php setup.php TOOL_BASE_URL STEPS RUN (RUN names this run's course and users)
define('CLI_SCRIPT', true);
require(__DIR__ . '/config.php');
require_once($CFG->dirroot . '/mod/lti/locallib.php');
require_once($CFG->libdir . '/testing/generator/lib.php');

[$script, $base, $steps, $run] = $argv;
\core\session\manager::set_user(get_admin());
set_config('curlsecurityblockedhosts', '');  // the tool runs on this machine (loopback)
set_config('curlsecurityallowedport', '');
set_config('noreplyaddress', 'noreply@example.com');

$type = new stdClass();
$type->state = LTI_TOOL_STATE_CONFIGURED;
$config = new stdClass();
$config->lti_typename = 'Mehanizmi';
$config->lti_toolurl = "$base/lti/launch";
$config->lti_ltiversion = LTI_VERSION_1P3;
$config->lti_keytype = LTI_JWK_KEYSET;
$config->lti_publickeyset = "$base/lti/jwks";
$config->lti_initiatelogin = "$base/lti/login";
$config->lti_redirectionuris = "$base/lti/launch";
$config->lti_contentitem = 1;
$config->lti_toolurl_ContentItemSelectionRequest = "$base/lti/launch";
$config->lti_coursevisible = LTI_COURSEVISIBLE_ACTIVITYCHOOSER;
$config->lti_launchcontainer = LTI_LAUNCH_CONTAINER_WINDOW;
$config->lti_sendname = LTI_SETTING_NEVER;
$config->lti_sendemailaddr = LTI_SETTING_NEVER;
$config->lti_acceptgrades = LTI_SETTING_DELEGATE;  // (each activity says: a teacher's choice)
$config->ltiservice_gradesynchronization = 2;
$typeid = lti_add_type($type, $config);
$tool = lti_get_type($typeid);

$generator = new testing_data_generator();
$course = $generator->create_course(['fullname' => 'Mehanizmi poljoprivrednih mašina',
                                     'shortname' => "MPM-$run"]);
$teacher = $generator->create_user(['username' => "nastavnik$run", 'firstname' => 'Ana',
                                    'lastname' => 'Nastavnik']);
$student = $generator->create_user(['username' => "student$run", 'firstname' => 'Marko',
                                    'lastname' => 'Student']);
update_internal_user_password($teacher, 'Nastavnik-1!');  // (the generator's own is random)
update_internal_user_password($student, 'Student-1!');
$generator->enrol_user($teacher->id, $course->id, 'editingteacher');
$generator->enrol_user($student->id, $course->id, 'student');
$activity = $generator->create_module('lti', [
    'course' => $course->id, 'name' => 'Vežba: plan brzina i ubrzanja, 3.1', 'typeid' => $typeid,
    'toolurl' => "$base/lti/launch", 'instructorcustomparameters' => "task=zbirka-3.1\nmethod=plans",
    'grade' => (int) $steps, 'instructorchoiceacceptgrades' => 1,
    'launchcontainer' => LTI_LAUNCH_CONTAINER_WINDOW,
    // as a teacher's form leaves them (the test generator's own defaults would send a key
    // of its own as the token's audience, and names and e-mails)
    'resourcekey' => '', 'password' => '', 'instructorchoicesendname' => 0,
    'instructorchoicesendemailaddr' => 0]);

// an activity as a teacher types it without deep linking: the custom parameters, and no
// grade of its own (Moodle then sends only its line-items container; the tool makes one)
$typed = $generator->create_module('lti', [
    'course' => $course->id, 'name' => 'Vežba upisana ručno: plan brzina, 3.1', 'typeid' => $typeid,
    'toolurl' => "$base/lti/launch", 'instructorcustomparameters' => "task=zbirka-3.1\nmethod=plans",
    'grade' => 0, 'instructorchoiceacceptgrades' => 0, 'launchcontainer' => LTI_LAUNCH_CONTAINER_WINDOW,
    'resourcekey' => '', 'password' => '', 'instructorchoicesendname' => 0,
    'instructorchoicesendemailaddr' => 0]);

echo json_encode([
    'issuer' => $CFG->wwwroot, 'client_id' => $tool->clientid, 'deployment' => (string) $typeid,
    'auth_url' => "$CFG->wwwroot/mod/lti/auth.php", 'token_url' => "$CFG->wwwroot/mod/lti/token.php",
    'jwks_url' => "$CFG->wwwroot/mod/lti/certs.php", 'course' => $course->id,
    'cmid' => $activity->cmid, 'instance' => $activity->id, 'student' => $student->username,
    'teacher' => $teacher->username, 'student_id' => $student->id,
    'typed_cmid' => $typed->cmid, 'typed_instance' => $typed->id]), "\n";
