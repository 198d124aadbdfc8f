<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>inlay::studio::Autosaver</name>
    <message>
        <location filename="../app/studio/autosave.cpp" line="77"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1: kann nicht geschrieben werden (%2)</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Document</name>
    <message>
        <location filename="../app/studio/document.cpp" line="290"/>
        <location filename="../app/studio/document.cpp" line="308"/>
        <source>Preparation was cancelled.</source>
        <translation>Die Vorbereitung wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="404"/>
        <source>There is no object %1.</source>
        <translation>Es gibt kein Objekt %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="405"/>
        <source>The scene is still being prepared.</source>
        <translation>Die Szene wird noch vorbereitet.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="406"/>
        <source>The scene could not be prepared.</source>
        <translation>Die Szene konnte nicht vorbereitet werden.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="344"/>
        <location filename="../app/studio/document.cpp" line="572"/>
        <source>The position is not a number.</source>
        <translation>Die Position ist keine Zahl.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="346"/>
        <location filename="../app/studio/document.cpp" line="417"/>
        <source>The height must be greater than zero.</source>
        <translation>Die Höhe muss größer als null sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="368"/>
        <source>Move object %1</source>
        <translation>Objekt %1 verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="375"/>
        <source>Change height of object %1</source>
        <translation>Höhe von Objekt %1 ändern</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="382"/>
        <source>Turn object %1</source>
        <translation>Objekt %1 drehen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="389"/>
        <source>Change material of object %1</source>
        <translation>Material von Objekt %1 ändern</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="428"/>
        <source>Insert object %1</source>
        <translation>Objekt %1 einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="440"/>
        <source>Delete object %1</source>
        <translation>Objekt %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="537"/>
        <source>Open a photo first.</source>
        <translation>Öffnen Sie zuerst ein Foto.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="557"/>
        <source>There is no estimated box yet.</source>
        <translation>Es gibt noch keinen geschätzten Raum.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="562"/>
        <source>Accept the estimated box</source>
        <translation>Geschätzten Raum übernehmen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="568"/>
        <source>There is no such corner of the back wall.</source>
        <translation>Diese Ecke der Rückwand gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="578"/>
        <source>Move a corner of the back wall</source>
        <translation>Ecke der Rückwand verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="584"/>
        <source>Estimate the box again</source>
        <translation>Raum neu schätzen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="589"/>
        <source>A light&apos;s outline needs at least three points around an area.</source>
        <translation>Der Umriss einer Lampe braucht mindestens drei Punkte um eine Fläche.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="597"/>
        <source>Outline light %1</source>
        <translation>Lampe %1 umreißen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="603"/>
        <source>Each box of a shaft must be at least two pixels wide and high.</source>
        <translation>Jeder Rahmen eines Sonnenstrahls muss mindestens zwei Pixel breit und hoch sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="611"/>
        <source>Add shaft %1</source>
        <translation>Sonnenstrahl %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="618"/>
        <source>A surface&apos;s outline needs at least three points around an area.</source>
        <translation>Der Umriss einer Fläche braucht mindestens drei Punkte um eine Fläche.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="627"/>
        <source>Add surface %1</source>
        <translation>Fläche %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="638"/>
        <source>An occluder needs a stroke over the thing in front and one over what is behind it.</source>
        <translation>Ein Verdecker braucht einen Strich über dem, was davor ist, und einen über dem, was dahinter ist.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="643"/>
        <source>Add occluder %1</source>
        <translation>Verdecker %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="650"/>
        <source>There is no such occluder, or the stroke is empty.</source>
        <translation>Diesen Verdecker gibt es nicht, oder der Strich ist leer.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="656"/>
        <source>Add a stroke to occluder %1</source>
        <translation>Strich zu Verdecker %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="667"/>
        <source>There is no such mark.</source>
        <translation>Diese Markierung gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="674"/>
        <source>Delete light %1</source>
        <translation>Lampe %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="675"/>
        <source>Delete shaft %1</source>
        <translation>Sonnenstrahl %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="676"/>
        <source>Delete surface %1</source>
        <translation>Fläche %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="677"/>
        <source>Delete occluder %1</source>
        <translation>Verdecker %1 löschen</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LayersDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="140"/>
        <source>Layers</source>
        <translation>Ebenen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="142"/>
        <source>Composite</source>
        <translation>Komposit</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="142"/>
        <source>Photo</source>
        <translation>Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="143"/>
        <source>Albedo</source>
        <translation>Albedo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="143"/>
        <source>Direct light</source>
        <translation>Direktes Licht</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="144"/>
        <source>With objects</source>
        <translation>Mit Objekten</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="144"/>
        <source>Without objects</source>
        <translation>Ohne Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="145"/>
        <source>Mask</source>
        <translation>Maske</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="145"/>
        <source>Difference</source>
        <translation>Differenz</translation>
    </message>
</context>
<context>
    <name>inlay::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="80"/>
        <source>Reading the photo</source>
        <translation>Foto wird gelesen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="81"/>
        <source>Estimating the camera</source>
        <translation>Kamera wird geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="82"/>
        <source>Fitting the room</source>
        <translation>Raum wird angepasst</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="83"/>
        <source>Estimating the lighting</source>
        <translation>Beleuchtung wird geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="84"/>
        <source>Placing the objects</source>
        <translation>Objekte werden platziert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="116"/>
        <source>Samples per pixel of the shown composite</source>
        <translation>Samples pro Pixel des angezeigten Komposits</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="117"/>
        <source>Samples per second of the renderer (millions)</source>
        <translation>Samples pro Sekunde des Renderers (Millionen)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="118"/>
        <source>Estimated error (RMSE in sRGB) where the objects change the photo</source>
        <translation>Geschätzter Fehler (RMSE in sRGB), wo die Objekte das Foto verändern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="119"/>
        <source>Render time since the last change</source>
        <translation>Renderzeit seit der letzten Änderung</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="120"/>
        <source>Zoom</source>
        <translation>Zoom</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="121"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="132"/>
        <source>Preparing the scene: %1…</source>
        <translation>Szene wird vorbereitet: %1 …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="162"/>
        <source>&amp;Open Scene…</source>
        <translation>Szene &amp;öffnen …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="164"/>
        <source>Open a scene file (.json)</source>
        <translation>Eine Szenendatei (.json) öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="167"/>
        <source>Open &amp;Photo…</source>
        <translation>&amp;Foto öffnen …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="169"/>
        <source>Start a new scene from a photo</source>
        <translation>Eine neue Szene aus einem Foto beginnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="172"/>
        <source>Open &amp;Example</source>
        <translation>&amp;Beispiel öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="175"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="179"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="183"/>
        <source>&amp;Export Composite…</source>
        <translation>Komposit &amp;exportieren …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="185"/>
        <source>Write the current composite as PNG, JPEG, TIFF or EXR</source>
        <translation>Das aktuelle Komposit als PNG, JPEG, TIFF oder EXR schreiben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="188"/>
        <source>Export Shown &amp;Layer…</source>
        <translation>Angezeigte &amp;Ebene exportieren…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="189"/>
        <source>Write the layer the viewport shows (albedo, mask, …) as an 8-bit image</source>
        <translation>Die angezeigte Ebene (Albedo, Maske, …) als 8-Bit-Bild schreiben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="191"/>
        <source>Export Scene as &amp;glTF…</source>
        <translation>Szene als &amp;glTF exportieren…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="192"/>
        <source>Write the room, its lights, the camera and the objects as glTF 2.0, to go on in Blender</source>
        <translation>Raum, Lichter, Kamera und Objekte als glTF 2.0 schreiben, um in Blender weiterzuarbeiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="195"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="199"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="202"/>
        <source>&amp;Redo</source>
        <translation>Wi&amp;ederholen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="206"/>
        <source>Insert &amp;Sphere</source>
        <translation>&amp;Kugel einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="207"/>
        <source>Stand a sphere on the floor in the middle of the photo</source>
        <translation>Eine Kugel in der Bildmitte auf den Boden stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="210"/>
        <source>Insert &amp;Cube</source>
        <translation>&amp;Würfel einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="211"/>
        <source>Stand a cube on the floor in the middle of the photo</source>
        <translation>Einen Würfel in der Bildmitte auf den Boden stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="214"/>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="215"/>
        <source>Delete the selected object or mark</source>
        <translation>Das ausgewählte Objekt oder die ausgewählte Markierung löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="219"/>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="222"/>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="225"/>
        <source>&amp;Fit to Window</source>
        <translation>An &amp;Fenster anpassen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="228"/>
        <source>&amp;Before (Photo Only)</source>
        <translation>&amp;Vorher (nur Foto)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="231"/>
        <source>Toggle between the photo and the composite with the objects</source>
        <translation>Zwischen dem Foto und dem Komposit mit den Objekten umschalten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="234"/>
        <source>&amp;Accept Estimated Box</source>
        <translation>Geschätzten &amp;Raum übernehmen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="235"/>
        <source>Keep the estimated back wall as yours</source>
        <translation>Die geschätzte Rückwand als Ihre behalten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="240"/>
        <source>Estimate the &amp;Box Again</source>
        <translation>Raum &amp;neu schätzen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="241"/>
        <source>Forget your corners of the back wall</source>
        <translation>Ihre Ecken der Rückwand verwerfen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="246"/>
        <source>&amp;Prepare the Scene Again</source>
        <translation>Szene erneut &amp;vorbereiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="248"/>
        <source>Estimate the camera, room and lighting again (after a cancel)</source>
        <translation>Kamera, Raum und Beleuchtung erneut schätzen (nach einem Abbruch)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="250"/>
        <source>&amp;Vanishing Lines and Confidence</source>
        <translation>&amp;Fluchtlinien und Konfidenz</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="257"/>
        <source>&amp;Select and Move</source>
        <translation>&amp;Auswählen und verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="258"/>
        <source>Outline a &amp;Light</source>
        <translation>&amp;Lampe umreißen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="259"/>
        <source>Sun &amp;Shaft</source>
        <translation>&amp;Sonnenstrahl</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="260"/>
        <source>&amp;Table Top or Step</source>
        <translation>&amp;Tischplatte oder Stufe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="261"/>
        <source>&amp;Occluder Strokes</source>
        <translation>&amp;Verdecker-Striche</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="271"/>
        <source>&amp;About Inlay</source>
        <translation>&amp;Über Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="276"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="280"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="292"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="304"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="307"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="319"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="323"/>
        <source>System Default</source>
        <translation>Systemvorgabe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="334"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="337"/>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="357"/>
        <location filename="../app/studio/main_window.cpp" line="366"/>
        <source>Preparing the scene…</source>
        <translation>Szene wird vorbereitet …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="357"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="358"/>
        <location filename="../app/studio/main_window.cpp" line="776"/>
        <source>Inlay</source>
        <translation>Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="382"/>
        <source>The scene could not be prepared</source>
        <translation>Die Szene konnte nicht vorbereitet werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/main_window.cpp" line="391"/>
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (und %n weiterer Hinweis)</numerusform>
            <numerusform>%1 (und %n weitere Hinweise)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="418"/>
        <source>– spp</source>
        <translation>– spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="419"/>
        <location filename="../app/studio/main_window.cpp" line="431"/>
        <source>– samples/s</source>
        <translation>– Samples/s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="420"/>
        <source>error –</source>
        <translation>Fehler –</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="421"/>
        <source>– s</source>
        <translation>– s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="425"/>
        <source>preview 1/%1</source>
        <translation>Vorschau 1/%1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="426"/>
        <source>%1 spp, done</source>
        <translation>%1 spp, fertig</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="427"/>
        <source>%1 spp</source>
        <translation>%1 spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="428"/>
        <source>error %1</source>
        <translation>Fehler %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="430"/>
        <source>%1 M samples/s</source>
        <translation>%1 Mio. Samples/s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="432"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="442"/>
        <source>%1 (new scene)</source>
        <translation>%1 (neue Szene)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="445"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="446"/>
        <source>%1[*] — Inlay</source>
        <translation>%1[*] — Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="465"/>
        <source>Cannot open</source>
        <translation>Öffnen nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="465"/>
        <source>%1: no such file</source>
        <translation>%1: Datei nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="471"/>
        <source>Cannot open the scene</source>
        <translation>Die Szene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="490"/>
        <location filename="../app/studio/main_window.cpp" line="500"/>
        <source>Cannot open the example</source>
        <translation>Das Beispiel kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="490"/>
        <source>The example scene is not installed.</source>
        <translation>Die Beispielszene ist nicht installiert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="500"/>
        <source>Cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="510"/>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="511"/>
        <source>Inlay scenes (*.json);;All files (*)</source>
        <translation>Inlay-Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="518"/>
        <source>Open Photo</source>
        <translation>Foto öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="519"/>
        <source>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;All files (*)</source>
        <translation>Fotos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="526"/>
        <source>Cannot save the scene</source>
        <translation>Die Szene kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="530"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="545"/>
        <source>Save Scene As</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="546"/>
        <source>Inlay scenes (*.json)</source>
        <translation>Inlay-Szenen (*.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="554"/>
        <location filename="../app/studio/main_window.cpp" line="575"/>
        <location filename="../app/studio/main_window.cpp" line="604"/>
        <location filename="../app/studio/main_window.cpp" line="633"/>
        <source>Nothing to export</source>
        <translation>Nichts zu exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="554"/>
        <location filename="../app/studio/main_window.cpp" line="575"/>
        <source>The composite has not been rendered yet.</source>
        <translation>Das Komposit wurde noch nicht gerendert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="558"/>
        <location filename="../app/studio/main_window.cpp" line="622"/>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="558"/>
        <location filename="../app/studio/main_window.cpp" line="622"/>
        <source>JPEG image (*.jpg *.jpeg)</source>
        <translation>JPEG-Bild (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="559"/>
        <location filename="../app/studio/main_window.cpp" line="623"/>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>TIFF-Bild (*.tif *.tiff)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="559"/>
        <source>OpenEXR, linear (*.exr)</source>
        <translation>OpenEXR, linear (*.exr)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="560"/>
        <source>Export Composite</source>
        <translation>Komposit exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="580"/>
        <source>Cannot export the composite</source>
        <translation>Das Komposit kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="583"/>
        <source>Exported %1 (%2 spp)</source>
        <translation>%1 exportiert (%2 spp)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="592"/>
        <source>glTF 2.0, separate files (*.gltf)</source>
        <translation>glTF 2.0, getrennte Dateien (*.gltf)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="592"/>
        <source>glTF 2.0, binary (*.glb)</source>
        <translation>glTF 2.0, binär (*.glb)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="593"/>
        <source>Export Scene as glTF</source>
        <translation>Szene als glTF exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="604"/>
        <source>The scene is not prepared yet.</source>
        <translation>Die Szene ist noch nicht vorbereitet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="610"/>
        <source>Cannot export the scene</source>
        <translation>Die Szene kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="621"/>
        <source>Export Shown Layer</source>
        <translation>Angezeigte Ebene exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="633"/>
        <source>This layer has not been made yet.</source>
        <translation>Diese Ebene wurde noch nicht berechnet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="640"/>
        <source>Cannot export the layer</source>
        <translation>Die Ebene kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="641"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1: kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="613"/>
        <location filename="../app/studio/main_window.cpp" line="644"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="665"/>
        <source>About Inlay</source>
        <translation>Über Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="666"/>
        <source>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Inserts synthetic objects into an ordinary photograph: a box room is fitted to the photo, its lights and reflectance are estimated, and a path tracer renders the objects into it (after Karsch et al., 2011).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Fügt synthetische Objekte in ein gewöhnliches Foto ein: Ein Quaderraum wird an das Foto angepasst, seine Lichter und Reflexionsgrade werden geschätzt, und ein Pfadverfolger rendert die Objekte hinein (nach Karsch et al., 2011).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="675"/>
        <source>There is no floor in the middle of the photo to stand an object on.</source>
        <translation>In der Bildmitte gibt es keinen Boden, auf dem ein Objekt stehen kann.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="727"/>
        <source>The language changes when Inlay is started again.</source>
        <translation>Die Sprache wechselt beim nächsten Start von Inlay.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="738"/>
        <source>a new scene</source>
        <translation>einer neuen Szene</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="741"/>
        <source>Restore unsaved work?</source>
        <translation>Ungesicherte Arbeit wiederherstellen?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="742"/>
        <source>Inlay did not close properly. Unsaved work on %1 was kept at %2. Restore it?</source>
        <translation>Inlay wurde nicht ordnungsgemäß beendet. Ungesicherte Arbeit an %1 wurde um %2 aufbewahrt. Wiederherstellen?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="746"/>
        <source>&amp;Restore</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="747"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="765"/>
        <source>Cannot restore the unsaved work</source>
        <translation>Die ungesicherte Arbeit kann nicht wiederhergestellt werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="769"/>
        <source>Restored the unsaved work.</source>
        <translation>Die ungesicherte Arbeit wurde wiederhergestellt.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="776"/>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>Die Szene hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PrepareWorker</name>
    <message>
        <location filename="../app/studio/prepare_worker.cpp" line="49"/>
        <source>Internal error while preparing the scene.</source>
        <translation>Interner Fehler beim Vorbereiten der Szene.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PropertiesDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="174"/>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="186"/>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="194"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="198"/>
        <source>Diffuse</source>
        <translation>Matt (diffus)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="199"/>
        <source>Glossy</source>
        <translation>Glänzend</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="200"/>
        <source>Mirror</source>
        <translation>Spiegel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="201"/>
        <source>Metal</source>
        <translation>Metall</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="202"/>
        <source>Glass</source>
        <translation>Glas</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="203"/>
        <source>Frosted glass</source>
        <translation>Milchglas</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="204"/>
        <source>Emissive</source>
        <translation>Leuchtend</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="205"/>
        <source>From the file</source>
        <translation>Aus der Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="208"/>
        <source>Reflectance of the object&apos;s surface</source>
        <translation>Reflexionsgrad der Objektoberfläche</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="211"/>
        <source>Base (px):</source>
        <translation>Fußpunkt (px):</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="212"/>
        <source>Height:</source>
        <translation>Höhe:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="213"/>
        <source>Turn:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="214"/>
        <source>Material:</source>
        <translation>Material:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="215"/>
        <source>Colour:</source>
        <translation>Farbe:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="234"/>
        <source>No object selected</source>
        <translation>Kein Objekt ausgewählt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="239"/>
        <source>&lt;b&gt;Object %1&lt;/b&gt; (%2)</source>
        <translation>&lt;b&gt;Objekt %1&lt;/b&gt; (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="284"/>
        <source>Object colour</source>
        <translation>Objektfarbe</translation>
    </message>
</context>
<context>
    <name>inlay::studio::SceneTreeDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="30"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="31"/>
        <source>cube</source>
        <translation>Würfel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="45"/>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="47"/>
        <source>Item</source>
        <translation>Element</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="47"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="77"/>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="80"/>
        <source>%1 × %2 m, %3 m high</source>
        <translation>%1 × %2 m, %3 m hoch</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="85"/>
        <source>back wall given</source>
        <translation>Rückwand vorgegeben</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="85"/>
        <source>estimated</source>
        <translation>geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="88"/>
        <source>Lights</source>
        <translation>Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="91"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="92"/>
        <source>outline on the photo</source>
        <translation>Umriss im Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="93"/>
        <source>rectangle in 3D</source>
        <translation>Rechteck im Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="107"/>
        <source>Shafts</source>
        <translation>Sonnenstrahlen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="107"/>
        <source>Shaft %1</source>
        <translation>Sonnenstrahl %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="108"/>
        <source>sunlit patch and its window</source>
        <translation>Sonnenfleck und sein Fenster</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="109"/>
        <source>Surfaces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="109"/>
        <source>Surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="111"/>
        <source>Occluders</source>
        <translation>Verdecker</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="111"/>
        <source>Occluder %1</source>
        <translation>Verdecker %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="113"/>
        <source>%1 strokes in front, %2 behind</source>
        <translation>%1 Striche davor, %2 dahinter</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="118"/>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="122"/>
        <source>Object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="123"/>
        <source>%1, %2 m</source>
        <translation>%1, %2 m</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Viewport</name>
    <message>
        <location filename="../app/studio/viewport.cpp" line="273"/>
        <source>Drag an object or a corner of the back wall.</source>
        <translation>Ziehen Sie ein Objekt oder eine Ecke der Rückwand.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="275"/>
        <source>Click around a light; click the first point (or press Enter) to close.</source>
        <translation>Klicken Sie um eine Lampe herum; ein Klick auf den ersten Punkt (oder Eingabe) schließt den Umriss.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="277"/>
        <source>Now drag a box around the window the sunlight comes through.</source>
        <translation>Ziehen Sie nun einen Rahmen um das Fenster, durch das die Sonne scheint.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="278"/>
        <source>Drag a box around the patch of sunlight.</source>
        <translation>Ziehen Sie einen Rahmen um den Sonnenfleck.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="281"/>
        <source>Click the floor straight below the first point of the outline.</source>
        <translation>Klicken Sie auf den Boden genau unter dem ersten Punkt des Umrisses.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="282"/>
        <source>Click around the top of a table or step; click the first point to close.</source>
        <translation>Klicken Sie um eine Tischplatte oder Stufe herum; ein Klick auf den ersten Punkt schließt den Umriss.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="284"/>
        <source>Left drag over the thing in front, right drag over what is behind it; Enter starts another occluder.</source>
        <translation>Mit links über das ziehen, was davor ist, mit rechts über das, was dahinter ist; Eingabe beginnt einen weiteren Verdecker.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="355"/>
        <source>Back wall (yours)</source>
        <translation>Rückwand (Ihre)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="355"/>
        <source>Back wall (estimated)</source>
        <translation>Rückwand (geschätzt)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="411"/>
        <source>%1 px</source>
        <translation>%1 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="439"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="453"/>
        <source>Shaft %1</source>
        <translation>Sonnenstrahl %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="468"/>
        <source>Surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="614"/>
        <source>Preparing the scene…</source>
        <translation>Szene wird vorbereitet …</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="617"/>
        <source>The scene could not be prepared: %1</source>
        <translation>Die Szene konnte nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="621"/>
        <source>Open a scene or a photo (File menu).</source>
        <translation>Öffnen Sie eine Szene oder ein Foto (Menü Datei).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="624"/>
        <source>Before: the photo without objects</source>
        <translation>Vorher: das Foto ohne Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="642"/>
        <source>Vanishing points: x %1, y %2, z %3 (confidence)</source>
        <translation>Fluchtpunkte: x %1, y %2, z %3 (Konfidenz)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="646"/>
        <source>Focal length %1 px (%2–%3 px)</source>
        <translation>Brennweite %1 px (%2–%3 px)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="686"/>
        <source>An outline needs at least three points.</source>
        <translation>Ein Umriss braucht mindestens drei Punkte.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="817"/>
        <location filename="../app/studio/viewport.cpp" line="919"/>
        <source>Cannot place the object here: %1</source>
        <translation>Das Objekt kann hier nicht stehen: %1</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/studio/main.cpp" line="47"/>
        <source>Insert synthetic objects into a photograph.</source>
        <translation>Synthetische Objekte in ein Foto einfügen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="52"/>
        <source>A scene file (.json) or a photo; none: the example.</source>
        <translation>Eine Szenendatei (.json) oder ein Foto; ohne Angabe: das Beispiel.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="56"/>
        <source>Grab the window to &lt;file&gt; once rendered, then exit.</source>
        <translation>Das Fenster nach dem Rendern in &lt;file&gt; speichern, dann beenden.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="60"/>
        <source>Samples per pixel to wait for (default 4).</source>
        <translation>Abzuwartende Samples pro Pixel (Vorgabe 4).</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="64"/>
        <source>Restore unsaved work left by a crash without asking.</source>
        <translation>Ungesicherte Arbeit nach einem Absturz ohne Nachfrage wiederherstellen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="79"/>
        <source>Give at most one file.</source>
        <translation>Geben Sie höchstens eine Datei an.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="86"/>
        <source>expected a number &gt;= 0</source>
        <translation>eine Zahl &gt;= 0 erwartet</translation>
    </message>
</context>
</TS>
