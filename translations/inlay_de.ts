<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>inlay::studio::Autosaver</name>
    <message>
        <location filename="../app/studio/autosave.cpp" line="60"/>
        <source>%1: cannot take the lock</source>
        <translation>%1: die Sperre lässt sich nicht setzen</translation>
    </message>
    <message>
        <location filename="../app/studio/autosave.cpp" line="102"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1: kann nicht geschrieben werden (%2)</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Document</name>
    <message>
        <location filename="../app/studio/document.cpp" line="298"/>
        <location filename="../app/studio/document.cpp" line="328"/>
        <source>Preparation was cancelled.</source>
        <translation>Die Vorbereitung wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="496"/>
        <source>There is no object %1.</source>
        <translation>Es gibt kein Objekt %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="497"/>
        <source>The scene is still being prepared.</source>
        <translation>Die Szene wird noch vorbereitet.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="498"/>
        <source>The scene could not be prepared.</source>
        <translation>Die Szene konnte nicht vorbereitet werden.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="384"/>
        <location filename="../app/studio/document.cpp" line="789"/>
        <location filename="../app/studio/document.cpp" line="971"/>
        <location filename="../app/studio/document.cpp" line="1028"/>
        <source>The position is not a number.</source>
        <translation>Die Position ist keine Zahl.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="386"/>
        <location filename="../app/studio/document.cpp" line="509"/>
        <location filename="../app/studio/document.cpp" line="526"/>
        <source>The height must be greater than zero.</source>
        <translation>Die Höhe muss größer als null sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="407"/>
        <location filename="../app/studio/document.cpp" line="438"/>
        <source>Move object %1</source>
        <translation>Objekt %1 verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="414"/>
        <source>Change height of object %1</source>
        <translation>Höhe von Objekt %1 ändern</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="420"/>
        <location filename="../app/studio/document.cpp" line="432"/>
        <source>The turn is not a number.</source>
        <translation>Die Drehung ist keine Zahl.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="425"/>
        <source>Turn object %1</source>
        <translation>Objekt %1 drehen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="481"/>
        <source>Change material of object %1</source>
        <translation>Material von Objekt %1 ändern</translation>
    </message>
    <message>
        <source>Insert object %1</source>
        <translation type="vanished">Objekt %1 einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="524"/>
        <source>The model has no triangles.</source>
        <translation>Das Modell hat keine Dreiecke.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="532"/>
        <source>object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="533"/>
        <source>Insert %1</source>
        <translation>%1 einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="550"/>
        <source>Duplicate %1</source>
        <translation>%1 duplizieren</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="598"/>
        <source>Rename %1</source>
        <translation>%1 umbenennen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="605"/>
        <source>Hide %1</source>
        <translation>%1 ausblenden</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="605"/>
        <source>Show %1</source>
        <translation>%1 einblenden</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="613"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="614"/>
        <source>cube</source>
        <translation>Würfel</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="652"/>
        <source>Delete object %1</source>
        <translation>Objekt %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="754"/>
        <source>Open a photo first.</source>
        <translation>Öffnen Sie zuerst ein Foto.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="774"/>
        <source>There is no estimated box yet.</source>
        <translation>Es gibt noch keinen geschätzten Raum.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="779"/>
        <source>Accept the estimated box</source>
        <translation>Geschätzten Raum übernehmen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="785"/>
        <source>There is no such corner of the back wall.</source>
        <translation>Diese Ecke der Rückwand gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="795"/>
        <source>Move a corner of the back wall</source>
        <translation>Ecke der Rückwand verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="801"/>
        <source>Estimate the box again</source>
        <translation>Raum neu schätzen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="806"/>
        <source>A light&apos;s outline needs at least three points around an area.</source>
        <translation>Der Umriss einer Lampe braucht mindestens drei Punkte um eine Fläche.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="814"/>
        <source>Outline light %1</source>
        <translation>Lampe %1 umreißen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="820"/>
        <location filename="../app/studio/document.cpp" line="991"/>
        <source>Each box of a shaft must be at least two pixels wide and high.</source>
        <translation>Jeder Rahmen eines Sonnenstrahls muss mindestens zwei Pixel breit und hoch sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="828"/>
        <source>Add shaft %1</source>
        <translation>Sonnenstrahl %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="835"/>
        <source>A surface&apos;s outline needs at least three points around an area.</source>
        <translation>Der Umriss einer Fläche braucht mindestens drei Punkte um eine Fläche.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="844"/>
        <source>Add surface %1</source>
        <translation>Fläche %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="855"/>
        <source>An occluder needs a stroke over the thing in front and one over what is behind it.</source>
        <translation>Ein Verdecker braucht einen Strich über dem, was davor ist, und einen über dem, was dahinter ist.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="860"/>
        <source>Add occluder %1</source>
        <translation>Verdecker %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="867"/>
        <source>There is no such occluder, or the stroke is empty.</source>
        <translation>Diesen Verdecker gibt es nicht, oder der Strich ist leer.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="873"/>
        <source>Add a stroke to occluder %1</source>
        <translation>Strich zu Verdecker %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="884"/>
        <source>There is no such mark.</source>
        <translation>Diese Markierung gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="891"/>
        <source>Delete light %1</source>
        <translation>Lampe %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="892"/>
        <source>Delete shaft %1</source>
        <translation>Sonnenstrahl %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="893"/>
        <source>Delete surface %1</source>
        <translation>Fläche %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="894"/>
        <source>Delete occluder %1</source>
        <translation>Verdecker %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="974"/>
        <source>There is no such point.</source>
        <translation>Diesen Punkt gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="982"/>
        <location filename="../app/studio/document.cpp" line="1000"/>
        <source>The outline would lose its area.</source>
        <translation>Der Umriss würde seine Fläche verlieren.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="983"/>
        <source>Reshape light %1</source>
        <translation>Licht %1 umformen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="992"/>
        <source>Reshape shaft %1</source>
        <translation>Lichtschacht %1 umformen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1001"/>
        <source>Reshape surface %1</source>
        <translation>Fläche %1 umformen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1009"/>
        <source>Reshape occluder %1</source>
        <translation>Verdecker %1 umformen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1025"/>
        <source>There is no such axis.</source>
        <translation>Diese Achse gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1030"/>
        <source>Each line must be at least two pixels long.</source>
        <translation>Jede Linie muss mindestens zwei Pixel lang sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1034"/>
        <source>The two lines lie on one line: draw two different edges.</source>
        <translation>Die beiden Linien liegen auf einer Geraden: Zeichnen Sie zwei verschiedene Kanten.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1043"/>
        <source>Draw the %1 vanishing lines</source>
        <translation>Fluchtlinien für %1 zeichnen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1044"/>
        <source>Forget the %1 vanishing lines</source>
        <translation>Fluchtlinien für %1 verwerfen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1058"/>
        <source>The room has no surface %1.</source>
        <translation>Der Raum hat keine Fläche %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1061"/>
        <source>Unknown material.</source>
        <translation>Unbekanntes Material.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1064"/>
        <source>The roughness must lie between 0 and 1.</source>
        <translation>Die Rauheit muss zwischen 0 und 1 liegen.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1070"/>
        <source>Change the material of %1</source>
        <translation>Material von %1 ändern</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1076"/>
        <source>Change the camera response</source>
        <translation>Kamerakennlinie ändern</translation>
    </message>
</context>
<context>
    <name>inlay::studio::FinalRender</name>
    <message>
        <location filename="../app/studio/final_render.cpp" line="73"/>
        <source>Render Final Image cancelled; nothing was written.</source>
        <translation>Endgültiges Bild abgebrochen; nichts wurde geschrieben.</translation>
    </message>
    <message>
        <location filename="../app/studio/final_render.cpp" line="115"/>
        <source>Wrote %1: %2 × %3, %4 samples per pixel at most (%5 on average), estimated error %6, %7 s</source>
        <translation>%1 geschrieben: %2 × %3, höchstens %4 Samples pro Pixel (%5 im Mittel), geschätzter Fehler %6, %7 s</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LayersDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="195"/>
        <source>Layers</source>
        <translation>Ebenen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="196"/>
        <source>Composite</source>
        <translation>Komposit</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="196"/>
        <source>Photo</source>
        <translation>Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="197"/>
        <source>Albedo</source>
        <translation>Albedo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="197"/>
        <source>Direct light</source>
        <translation>Direktes Licht</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="198"/>
        <source>With objects</source>
        <translation>Mit Objekten</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="198"/>
        <source>Without objects</source>
        <translation>Ohne Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="199"/>
        <source>Mask</source>
        <translation>Maske</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="199"/>
        <source>Difference</source>
        <translation>Differenz</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LibraryDock</name>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="23"/>
        <source>Chair</source>
        <translation>Stuhl</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="24"/>
        <source>Armchair</source>
        <translation>Sessel</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="25"/>
        <source>Sofa</source>
        <translation>Sofa</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="26"/>
        <source>Coffee table</source>
        <translation>Couchtisch</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="27"/>
        <source>Dining table</source>
        <translation>Esstisch</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="28"/>
        <source>Stool</source>
        <translation>Hocker</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="29"/>
        <source>Floor lamp</source>
        <translation>Stehlampe</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="30"/>
        <source>Table lamp</source>
        <translation>Tischlampe</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="31"/>
        <source>Vase</source>
        <translation>Vase</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="32"/>
        <source>Potted plant</source>
        <translation>Topfpflanze</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="33"/>
        <source>Bookshelf</source>
        <translation>Bücherregal</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="34"/>
        <source>Rug</source>
        <translation>Teppich</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="101"/>
        <source>Library</source>
        <translation>Bibliothek</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="104"/>
        <source>The model library could not be shown: %1</source>
        <translation>Die Modellbibliothek kann nicht angezeigt werden: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="110"/>
        <source>%1
%2 × %3 × %4 m (width × depth × height)
Drag it into the photo.</source>
        <translation>%1
%2 × %3 × %4 m (Breite × Tiefe × Höhe)
Ins Foto ziehen, um es einzusetzen.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="86"/>
        <source>Reading the photo</source>
        <translation>Foto wird gelesen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="87"/>
        <source>Estimating the camera</source>
        <translation>Kamera wird geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="88"/>
        <source>Fitting the room</source>
        <translation>Raum wird angepasst</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="89"/>
        <source>Estimating the lighting</source>
        <translation>Beleuchtung wird geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="90"/>
        <source>Placing the objects</source>
        <translation>Objekte werden platziert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="461"/>
        <source>Samples per pixel of the shown composite</source>
        <translation>Samples pro Pixel des angezeigten Komposits</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="462"/>
        <source>Samples per second of the renderer (millions)</source>
        <translation>Samples pro Sekunde des Renderers (Millionen)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="463"/>
        <source>Estimated error (RMSE in sRGB) where the objects change the photo</source>
        <translation>Geschätzter Fehler (RMSE in sRGB), wo die Objekte das Foto verändern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="464"/>
        <source>Render time since the last change</source>
        <translation>Renderzeit seit der letzten Änderung</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="465"/>
        <source>Zoom</source>
        <translation>Zoom</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="125"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="138"/>
        <source>Preparing the scene: %1…</source>
        <translation>Szene wird vorbereitet: %1 …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="414"/>
        <source>&amp;Open Scene…</source>
        <translation>Szene &amp;öffnen …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="449"/>
        <source>Open a scene file (.json)</source>
        <translation>Eine Szenendatei (.json) öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="415"/>
        <source>Open &amp;Photo…</source>
        <translation>&amp;Foto öffnen …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="450"/>
        <source>Start a new scene from a photo</source>
        <translation>Eine neue Szene aus einem Foto beginnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="416"/>
        <source>Open &amp;Example</source>
        <translation>&amp;Beispiel öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="417"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="418"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="419"/>
        <source>&amp;Export Composite…</source>
        <translation>Komposit &amp;exportieren …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="451"/>
        <source>Write the current composite as PNG, JPEG, TIFF or EXR</source>
        <translation>Das aktuelle Komposit als PNG, JPEG, TIFF oder EXR schreiben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="420"/>
        <source>Export Shown &amp;Layer…</source>
        <translation>Angezeigte &amp;Ebene exportieren…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="452"/>
        <source>Write the layer the viewport shows (albedo, mask, …) as an 8-bit image</source>
        <translation>Die angezeigte Ebene (Albedo, Maske, …) als 8-Bit-Bild schreiben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="421"/>
        <source>Export Scene as &amp;glTF…</source>
        <translation>Szene als &amp;glTF exportieren…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="453"/>
        <source>Write the room, its lights, the camera and the objects as glTF 2.0, to go on in Blender</source>
        <translation>Raum, Lichter, Kamera und Objekte als glTF 2.0 schreiben, um in Blender weiterzuarbeiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="427"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="488"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="489"/>
        <source>&amp;Redo</source>
        <translation>Wi&amp;ederholen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="428"/>
        <source>Insert &amp;Sphere</source>
        <translation>&amp;Kugel einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="454"/>
        <source>Stand a sphere on the floor in the middle of the photo</source>
        <translation>Eine Kugel in der Bildmitte auf den Boden stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="429"/>
        <source>Insert &amp;Cube</source>
        <translation>&amp;Würfel einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="455"/>
        <source>Stand a cube on the floor in the middle of the photo</source>
        <translation>Einen Würfel in der Bildmitte auf den Boden stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="430"/>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="456"/>
        <source>Delete the selected object or mark</source>
        <translation>Das ausgewählte Objekt oder die ausgewählte Markierung löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="440"/>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="441"/>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="442"/>
        <source>&amp;Fit to Window</source>
        <translation>An &amp;Fenster anpassen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="443"/>
        <source>&amp;Before (Photo Only)</source>
        <translation>&amp;Vorher (nur Foto)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="457"/>
        <source>Toggle between the photo and the composite with the objects</source>
        <translation>Zwischen dem Foto und dem Komposit mit den Objekten umschalten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="444"/>
        <source>&amp;Accept Estimated Box</source>
        <translation>Geschätzten &amp;Raum übernehmen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="458"/>
        <source>Keep the estimated back wall as yours</source>
        <translation>Die geschätzte Rückwand als Ihre behalten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="445"/>
        <source>Estimate the &amp;Box Again</source>
        <translation>Raum &amp;neu schätzen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="459"/>
        <source>Forget your corners of the back wall</source>
        <translation>Ihre Ecken der Rückwand verwerfen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="446"/>
        <source>&amp;Prepare the Scene Again</source>
        <translation>Szene erneut &amp;vorbereiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="460"/>
        <source>Estimate the camera, room and lighting again (after a cancel)</source>
        <translation>Kamera, Raum und Beleuchtung erneut schätzen (nach einem Abbruch)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="447"/>
        <source>&amp;Vanishing Lines and Confidence</source>
        <translation>&amp;Fluchtlinien und Konfidenz</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="466"/>
        <source>&amp;Select and Move</source>
        <translation>&amp;Auswählen und verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="466"/>
        <source>Outline a &amp;Light</source>
        <translation>&amp;Lampe umreißen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="466"/>
        <source>Sun &amp;Shaft</source>
        <translation>&amp;Sonnenstrahl</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="467"/>
        <source>&amp;Table Top or Step</source>
        <translation>&amp;Tischplatte oder Stufe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="467"/>
        <source>&amp;Occluder Strokes</source>
        <translation>&amp;Verdecker-Striche</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="448"/>
        <source>&amp;About Inlay</source>
        <translation>&amp;Über Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="422"/>
        <source>&amp;Render Final Image…</source>
        <translation>Endgültiges Bild &amp;rendern…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="423"/>
        <source>Render the composite at the photo&apos;s full resolution until it is clean, then save it (PNG, JPEG, TIFF or EXR)</source>
        <translation>Das Komposit in der vollen Auflösung des Fotos rendern, bis es rauschfrei ist, dann speichern (PNG, JPEG, TIFF oder EXR)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="425"/>
        <source>Before/After &amp;Split</source>
        <translation>Vorher/Nachher-&amp;Teilung</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="426"/>
        <source>The photo left of a divider, the composite right of it; drag the divider</source>
        <translation>Links einer Trennlinie das Foto, rechts das Komposit; die Trennlinie lässt sich ziehen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="431"/>
        <source>Insert &amp;Model…</source>
        <translation>&amp;Modell einfügen…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="432"/>
        <source>Stand a 3D model (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS) on the floor; or drop the file where it should stand</source>
        <translation>Ein 3D-Modell (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS) auf den Boden stellen; oder die Datei dort ablegen, wo es stehen soll</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="434"/>
        <source>D&amp;uplicate</source>
        <translation>D&amp;uplizieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="435"/>
        <source>Stand a copy of the selected object beside it</source>
        <translation>Eine Kopie des gewählten Objekts daneben stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="436"/>
        <source>Re&amp;name…</source>
        <translation>&amp;Umbenennen…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="437"/>
        <source>Rename the selected object (in the Scene list)</source>
        <translation>Das gewählte Objekt umbenennen (in der Szenenliste)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="438"/>
        <source>&amp;Hide or Show</source>
        <translation>Aus- oder &amp;Einblenden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="439"/>
        <source>Hide the selected object from the render, or show it again</source>
        <translation>Das gewählte Objekt aus dem Rendering ausblenden oder wieder einblenden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="468"/>
        <source>&amp;Vanishing Lines (X, Y, Z)</source>
        <translation>&amp;Fluchtlinien (X, Y, Z)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="470"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="471"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="472"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="473"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="474"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="475"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="476"/>
        <source>System Default</source>
        <translation>Systemvorgabe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="477"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="478"/>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="488"/>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="489"/>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederherstellen: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="496"/>
        <location filename="../app/studio/main_window.cpp" line="505"/>
        <source>Preparing the scene…</source>
        <translation>Szene wird vorbereitet …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="496"/>
        <location filename="../app/studio/main_window.cpp" line="838"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="497"/>
        <location filename="../app/studio/main_window.cpp" line="1206"/>
        <source>Inlay</source>
        <translation>Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="524"/>
        <source>The scene could not be prepared</source>
        <translation>Die Szene konnte nicht vorbereitet werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/main_window.cpp" line="533"/>
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (und %n weiterer Hinweis)</numerusform>
            <numerusform>%1 (und %n weitere Hinweise)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="563"/>
        <source>%1: the scene could not be prepared, so the model has nowhere to stand.</source>
        <translation>%1: Die Szene ließ sich nicht vorbereiten, das Modell hat also keinen Platz.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="579"/>
        <source>– spp</source>
        <translation>– spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="580"/>
        <location filename="../app/studio/main_window.cpp" line="592"/>
        <source>– samples/s</source>
        <translation>– Samples/s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="581"/>
        <source>error –</source>
        <translation>Fehler –</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="582"/>
        <source>– s</source>
        <translation>– s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="586"/>
        <source>preview 1/%1</source>
        <translation>Vorschau 1/%1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="587"/>
        <source>%1 spp, done</source>
        <translation>%1 spp, fertig</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="588"/>
        <source>%1 spp</source>
        <translation>%1 spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="589"/>
        <source>error %1</source>
        <translation>Fehler %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="591"/>
        <source>%1 M samples/s</source>
        <translation>%1 Mio. Samples/s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="593"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="603"/>
        <source>%1 (new scene)</source>
        <translation>%1 (neue Szene)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="606"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="607"/>
        <source>%1[*] — Inlay</source>
        <translation>%1[*] — Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="626"/>
        <source>Cannot open</source>
        <translation>Öffnen nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="626"/>
        <source>%1: no such file</source>
        <translation>%1: Datei nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="632"/>
        <source>Cannot open the scene</source>
        <translation>Die Szene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="651"/>
        <location filename="../app/studio/main_window.cpp" line="661"/>
        <source>Cannot open the example</source>
        <translation>Das Beispiel kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="651"/>
        <source>The example scene is not installed.</source>
        <translation>Die Beispielszene ist nicht installiert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="661"/>
        <source>Cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="671"/>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="672"/>
        <source>Inlay scenes (*.json);;All files (*)</source>
        <translation>Inlay-Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="679"/>
        <source>Open Photo</source>
        <translation>Foto öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="680"/>
        <source>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;All files (*)</source>
        <translation>Fotos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="687"/>
        <source>Cannot save the scene</source>
        <translation>Die Szene kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="691"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="706"/>
        <source>Save Scene As</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="707"/>
        <source>Inlay scenes (*.json)</source>
        <translation>Inlay-Szenen (*.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="715"/>
        <location filename="../app/studio/main_window.cpp" line="736"/>
        <location filename="../app/studio/main_window.cpp" line="899"/>
        <location filename="../app/studio/main_window.cpp" line="928"/>
        <source>Nothing to export</source>
        <translation>Nichts zu exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="715"/>
        <location filename="../app/studio/main_window.cpp" line="736"/>
        <source>The composite has not been rendered yet.</source>
        <translation>Das Komposit wurde noch nicht gerendert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="719"/>
        <location filename="../app/studio/main_window.cpp" line="797"/>
        <location filename="../app/studio/main_window.cpp" line="917"/>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="719"/>
        <location filename="../app/studio/main_window.cpp" line="797"/>
        <location filename="../app/studio/main_window.cpp" line="917"/>
        <source>JPEG image (*.jpg *.jpeg)</source>
        <translation>JPEG-Bild (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="720"/>
        <location filename="../app/studio/main_window.cpp" line="798"/>
        <location filename="../app/studio/main_window.cpp" line="918"/>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>TIFF-Bild (*.tif *.tiff)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="720"/>
        <location filename="../app/studio/main_window.cpp" line="798"/>
        <source>OpenEXR, linear (*.exr)</source>
        <translation>OpenEXR, linear (*.exr)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="721"/>
        <source>Export Composite</source>
        <translation>Komposit exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="744"/>
        <source>Cannot export the composite</source>
        <translation>Das Komposit kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="750"/>
        <source>Exported %1 (%2 spp, the preview&apos;s %3 × %4; Render Final Image writes the photo&apos;s full size)</source>
        <translation>%1 exportiert (%2 spp, die Vorschau mit %3 × %4; Endgültiges Bild rendern schreibt die volle Größe des Fotos)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="757"/>
        <source>Exported %1 (%2 spp)</source>
        <translation>%1 exportiert (%2 spp)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="782"/>
        <source>All four steps done. View &gt; Steps shows them again.</source>
        <translation>Alle vier Schritte erledigt. Ansicht &gt; Schritte zeigt sie wieder.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="788"/>
        <location filename="../app/studio/main_window.cpp" line="814"/>
        <source>Nothing to render</source>
        <translation>Nichts zu rendern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="799"/>
        <location filename="../app/studio/main_window.cpp" line="839"/>
        <source>Render Final Image</source>
        <translation>Endgültiges Bild rendern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="818"/>
        <source>A final image is being rendered already.</source>
        <translation>Ein endgültiges Bild wird bereits gerendert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="825"/>
        <location filename="../app/studio/main_window.cpp" line="830"/>
        <source>Cannot render the final image</source>
        <translation>Das endgültige Bild kann nicht gerendert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="826"/>
        <source>%1: choose a .png, .jpg, .tif or .exr file.</source>
        <translation>%1: bitte eine .png-, .jpg-, .tif- oder .exr-Datei wählen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="831"/>
        <source>%1: the folder %2 does not exist.</source>
        <translation>%1: der Ordner %2 existiert nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="838"/>
        <location filename="../app/studio/main_window.cpp" line="858"/>
        <source>Rendering the final image…</source>
        <translation>Das endgültige Bild wird gerendert…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="846"/>
        <source>Rendering the final image: %1 samples per pixel at most, estimated error %2 (target %3), %4 s</source>
        <translation>Endgültiges Bild: höchstens %1 Samples pro Pixel, geschätzter Fehler %2 (Ziel %3), %4 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="880"/>
        <source>Cannot write the final image</source>
        <translation>Das endgültige Bild kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="887"/>
        <source>glTF 2.0, separate files (*.gltf)</source>
        <translation>glTF 2.0, getrennte Dateien (*.gltf)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="887"/>
        <source>glTF 2.0, binary (*.glb)</source>
        <translation>glTF 2.0, binär (*.glb)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="888"/>
        <source>Export Scene as glTF</source>
        <translation>Szene als glTF exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="788"/>
        <location filename="../app/studio/main_window.cpp" line="814"/>
        <location filename="../app/studio/main_window.cpp" line="899"/>
        <source>The scene is not prepared yet.</source>
        <translation>Die Szene ist noch nicht vorbereitet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="905"/>
        <source>Cannot export the scene</source>
        <translation>Die Szene kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="916"/>
        <source>Export Shown Layer</source>
        <translation>Angezeigte Ebene exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="928"/>
        <source>This layer has not been made yet.</source>
        <translation>Diese Ebene wurde noch nicht berechnet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="935"/>
        <source>Cannot export the layer</source>
        <translation>Die Ebene kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="936"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1: kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="908"/>
        <location filename="../app/studio/main_window.cpp" line="939"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="964"/>
        <source>About Inlay</source>
        <translation>Über Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="965"/>
        <source>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Inserts synthetic objects into an ordinary photograph: a box room is fitted to the photo, its lights and reflectance are estimated, and a path tracer renders the objects into it (after Karsch et al., 2011).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Fügt synthetische Objekte in ein gewöhnliches Foto ein: Ein Quaderraum wird an das Foto angepasst, seine Lichter und Reflexionsgrade werden geschätzt, und ein Pfadverfolger rendert die Objekte hinein (nach Karsch et al., 2011).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="974"/>
        <source>There is no floor in the middle of the photo to stand an object on.</source>
        <translation>In der Bildmitte gibt es keinen Boden, auf dem ein Objekt stehen kann.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="999"/>
        <source>Insert Model</source>
        <translation>Modell einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1007"/>
        <source>%1: open a photo first; the model needs a room to stand in.</source>
        <translation>%1: Zuerst ein Foto öffnen; das Modell braucht einen Raum, in dem es steht.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1011"/>
        <source>%1: not a model file Inlay reads (%2).</source>
        <translation>%1: keine Modelldatei, die Inlay liest (%2).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1027"/>
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1037"/>
        <source>%1 goes in once the scene is prepared.</source>
        <translation>%1 wird eingefügt, sobald die Szene vorbereitet ist.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1047"/>
        <source>%1: there is no floor, table top or step under the drop point to stand it on.</source>
        <translation>%1: Unter der Ablagestelle gibt es keinen Boden, keine Tischplatte und keine Stufe, auf der es stehen kann.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1048"/>
        <source>%1: there is no floor in the middle of the photo to stand it on.</source>
        <translation>%1: In der Mitte des Fotos gibt es keinen Boden, auf dem es stehen kann.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1063"/>
        <source>%1 is %2 m high at its own size, taller than the room (%3 m): it was inserted %4 m high instead (change Height in Properties).</source>
        <translation>%1 ist in seiner eigenen Größe %2 m hoch, höher als der Raum (%3 m): Es wurde stattdessen %4 m hoch eingefügt (Höhe in den Eigenschaften ändern).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1077"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1080"/>
        <source>Inserted %1, %2 m high (its own size).</source>
        <translation>%1 eingefügt, %2 m hoch (seine eigene Größe).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1081"/>
        <source>Inserted %1, %2 m high.</source>
        <translation>%1 eingefügt, %2 m hoch.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1090"/>
        <source>Cannot insert the model</source>
        <translation>Das Modell lässt sich nicht einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1108"/>
        <source>Select an object to rename.</source>
        <translation>Ein Objekt zum Umbenennen auswählen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1138"/>
        <source>Models</source>
        <translation>Modelle</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1140"/>
        <source>Insert %1</source>
        <translation>%1 einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1166"/>
        <source>a new scene</source>
        <translation>einer neuen Szene</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1169"/>
        <source>Restore unsaved work?</source>
        <translation>Ungesicherte Arbeit wiederherstellen?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1170"/>
        <source>Inlay did not close properly. Unsaved work on %1 was kept at %2. Restore it?</source>
        <translation>Inlay wurde nicht ordnungsgemäß beendet. Ungesicherte Arbeit an %1 wurde um %2 aufbewahrt. Wiederherstellen?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1174"/>
        <source>&amp;Restore</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1175"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1193"/>
        <source>Cannot restore the unsaved work</source>
        <translation>Die ungesicherte Arbeit kann nicht wiederhergestellt werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1199"/>
        <source>Restored the unsaved work.</source>
        <translation>Die ungesicherte Arbeit wurde wiederhergestellt.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1206"/>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>Die Szene hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>inlay::studio::ModelImportText</name>
    <message>
        <location filename="../app/studio/model_import.cpp" line="12"/>
        <source>%1 km</source>
        <translation>%1 km</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="13"/>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="14"/>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="15"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="16"/>
        <source>%1 µm</source>
        <translation>%1 µm</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="31"/>
        <source>%1 files do not state their unit: %2 was scaled to %3 high (change Height in Properties).</source>
        <translation>%1-Dateien nennen ihre Einheit nicht: %2 wurde auf %3 Höhe skaliert (Höhe in den Eigenschaften ändern).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="42"/>
        <source>%1 says it is %2 high, an absurd size: it was inserted %3 high instead (change Height in Properties).</source>
        <translation>%1 gibt %2 Höhe an, eine absurde Größe: Es wurde stattdessen %3 hoch eingefügt (Höhe in den Eigenschaften ändern).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="63"/>
        <source>3D models (%1)</source>
        <translation>3D-Modelle (%1)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="64"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="78"/>
        <source>%1: not a model file Inlay reads (%2).</source>
        <translation>%1: keine Modelldatei, die Inlay liest (%2).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="96"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="99"/>
        <source>(Inlay inserts models of up to %1 triangles.)</source>
        <translation>(Inlay fügt Modelle mit bis zu %1 Dreiecken ein.)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="104"/>
        <source>%1: the model is flat (it has no height), so it cannot stand in the room.</source>
        <translation>%1: Das Modell ist flach (es hat keine Höhe) und kann daher nicht im Raum stehen.</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="113"/>
        <source>%1 has no normals: it is shaded flat.</source>
        <translation>%1 hat keine Normalen: Es wird flach schattiert.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PrepareWorker</name>
    <message>
        <location filename="../app/studio/prepare_worker.cpp" line="98"/>
        <source>Internal error while preparing the scene.</source>
        <translation>Interner Fehler beim Vorbereiten der Szene.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PropertiesDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="325"/>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="330"/>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="331"/>
        <source>Render:</source>
        <translation>Rendern:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="332"/>
        <source>Shown</source>
        <translation>Sichtbar</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="333"/>
        <source>A hidden object stays in the scene but is not rendered</source>
        <translation>Ein ausgeblendetes Objekt bleibt in der Szene, wird aber nicht gerendert</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="334"/>
        <source>Size (W × D × H):</source>
        <translation>Größe (B × T × H):</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="335"/>
        <source>Width × depth × height in metres, as placed (before its turn)</source>
        <translation>Breite × Tiefe × Höhe in Metern, wie platziert (vor der Drehung)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="337"/>
        <source>The photo pixel the centre of the object&apos;s base stands on</source>
        <translation>Der Fotopixel, auf dem die Mitte der Standfläche des Objekts steht</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="342"/>
        <source>Surface:</source>
        <translation>Fläche:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="343"/>
        <source>Finish:</source>
        <translation>Oberfläche:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="344"/>
        <source>Roughness:</source>
        <translation>Rauheit:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="345"/>
        <location filename="../app/studio/docks.cpp" line="357"/>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="346"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="347"/>
        <source>Diffuse</source>
        <translation>Matt (diffus)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="347"/>
        <location filename="../app/studio/docks.cpp" line="352"/>
        <source>Glossy</source>
        <translation>Glänzend</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="347"/>
        <location filename="../app/studio/docks.cpp" line="352"/>
        <source>Mirror</source>
        <translation>Spiegel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="347"/>
        <source>Metal</source>
        <translation>Metall</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="348"/>
        <source>Glass</source>
        <translation>Glas</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="348"/>
        <source>Frosted glass</source>
        <translation>Milchglas</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="348"/>
        <source>Emissive</source>
        <translation>Leuchtend</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="348"/>
        <source>From the file</source>
        <translation>Aus der Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="350"/>
        <source>Reflectance of the object&apos;s surface</source>
        <translation>Reflexionsgrad der Objektoberfläche</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="336"/>
        <source>Base (px):</source>
        <translation>Fußpunkt (px):</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="338"/>
        <location filename="../app/studio/docks.cpp" line="356"/>
        <source>Height:</source>
        <translation>Höhe:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="339"/>
        <source>Turn:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="340"/>
        <source>Material:</source>
        <translation>Material:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="341"/>
        <source>Colour:</source>
        <translation>Farbe:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="351"/>
        <source>&lt;b&gt;Room surface&lt;/b&gt;</source>
        <translation>&lt;b&gt;Raumfläche&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="352"/>
        <source>Matte</source>
        <translation>Matt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="354"/>
        <source>A real surface of the photo that reflects: a glossy floor, a mirror</source>
        <translation>Eine echte Fläche im Foto, die spiegelt: ein glänzender Boden, ein Spiegel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="355"/>
        <source>&lt;b&gt;New models&lt;/b&gt;</source>
        <translation>&lt;b&gt;Neue Modelle&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="358"/>
        <source>The height a model gets when its file does not state its unit (OBJ, PLY, 3DS) or states an absurd size</source>
        <translation>Die Höhe, die ein Modell erhält, wenn seine Datei keine Einheit nennt (OBJ, PLY, 3DS) oder eine absurde Größe angibt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="413"/>
        <source>No object selected</source>
        <translation>Kein Objekt ausgewählt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="420"/>
        <source>&lt;b&gt;Object %1&lt;/b&gt; (%2)</source>
        <translation>&lt;b&gt;Objekt %1&lt;/b&gt; (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="424"/>
        <source>%1 × %2 × %3 m</source>
        <translation>%1 × %2 × %3 m</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="428"/>
        <source>– (the scene is being prepared)</source>
        <translation>– (die Szene wird vorbereitet)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="473"/>
        <source>Object colour</source>
        <translation>Objektfarbe</translation>
    </message>
</context>
<context>
    <name>inlay::studio::ResponseCurveView</name>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="29"/>
        <source>code</source>
        <translation>Code</translation>
    </message>
</context>
<context>
    <name>inlay::studio::ResponseDock</name>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="51"/>
        <source>Camera Response</source>
        <translation>Kamerakennlinie</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="56"/>
        <source>Auto (estimated from the photo)</source>
        <translation>Automatisch (aus dem Foto geschätzt)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="57"/>
        <source>sRGB</source>
        <translation>sRGB</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="58"/>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="59"/>
        <source>Explicit (from the scene file)</source>
        <translation>Explizit (aus der Szenendatei)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="60"/>
        <source>How the photo&apos;s pixel values map to light (camera.response)</source>
        <translation>Wie die Pixelwerte des Fotos auf Licht abgebildet werden (camera.response)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="92"/>
        <source>Preparing the scene...</source>
        <translation>Die Szene wird vorbereitet...</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="98"/>
        <source>
Estimated from %1 edges in %2 ms.</source>
        <translation>
Aus %1 Kanten in %2 ms geschätzt.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::SceneTreeDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="36"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="37"/>
        <source>cube</source>
        <translation>Würfel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="96"/>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="97"/>
        <source>Item</source>
        <translation>Element</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="97"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="101"/>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="104"/>
        <source>%1 × %2 m, %3 m high</source>
        <translation>%1 × %2 m, %3 m hoch</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="109"/>
        <source>back wall given</source>
        <translation>Rückwand vorgegeben</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="109"/>
        <source>estimated</source>
        <translation>geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="112"/>
        <source>Lights</source>
        <translation>Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="115"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="116"/>
        <source>outline on the photo</source>
        <translation>Umriss im Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="117"/>
        <source>rectangle in 3D</source>
        <translation>Rechteck im Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="131"/>
        <source>Shafts</source>
        <translation>Sonnenstrahlen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="131"/>
        <source>Shaft %1</source>
        <translation>Sonnenstrahl %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="132"/>
        <source>sunlit patch and its window</source>
        <translation>Sonnenfleck und sein Fenster</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="133"/>
        <source>Surfaces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="133"/>
        <source>Surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="135"/>
        <source>Occluders</source>
        <translation>Verdecker</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="135"/>
        <source>Occluder %1</source>
        <translation>Verdecker %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="137"/>
        <source>%1 strokes in front, %2 behind</source>
        <translation>%1 Striche davor, %2 dahinter</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="142"/>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="147"/>
        <source>hidden: %1</source>
        <translation>ausgeblendet: %1</translation>
    </message>
    <message>
        <source>Object %1</source>
        <translation type="vanished">Objekt %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="145"/>
        <source>%1, %2 m</source>
        <translation>%1, %2 m</translation>
    </message>
</context>
<context>
    <name>inlay::studio::StepsDock</name>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="93"/>
        <source>no photo yet</source>
        <translation>noch kein Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="93"/>
        <source>Open Photo…</source>
        <translation>Foto öffnen…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="95"/>
        <source>the box is yours</source>
        <translation>Ihre eigene Box</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="97"/>
        <source>estimated: check that the back wall&apos;s corners sit on the room&apos;s corners</source>
        <translation>geschätzt: prüfen, ob die Ecken der Rückwand auf denen des Raums sitzen</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="98"/>
        <source>Accept the Box</source>
        <translation>Box übernehmen</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="100"/>
        <source>being estimated…</source>
        <translation>wird geschätzt…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="102"/>
        <source>not found: drag the back wall&apos;s corners onto the room&apos;s corners</source>
        <translation>nicht gefunden: die Ecken der Rückwand auf die des Raums ziehen</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="106"/>
        <source>none: objects are lit by gathered light only</source>
        <translation>keine: Objekte werden nur vom gesammelten Licht beleuchtet</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="106"/>
        <source>Outline a Light</source>
        <translation>Licht umreißen</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/steps_dock.cpp" line="109"/>
        <source>%n outlined</source>
        <translation>
            <numerusform>%n umrissen</numerusform>
            <numerusform>%n umrissen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="113"/>
        <source>none yet (or drag one from the Library)</source>
        <translation>noch keine (oder eines aus der Bibliothek ziehen)</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="113"/>
        <source>Insert Model…</source>
        <translation>Modell einfügen…</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/steps_dock.cpp" line="116"/>
        <source>%n in the photo</source>
        <translation>
            <numerusform>%n im Foto</numerusform>
            <numerusform>%n im Foto</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="119"/>
        <source>not yet</source>
        <translation>noch nicht</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="119"/>
        <source>Render Final Image…</source>
        <translation>Endgültiges Bild rendern…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="121"/>
        <source>written to %1</source>
        <translation>nach %1 geschrieben</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="149"/>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="150"/>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="150"/>
        <source>Lights</source>
        <translation>Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="150"/>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="150"/>
        <source>Export</source>
        <translation>Export</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Viewport</name>
    <message>
        <location filename="../app/studio/viewport.cpp" line="323"/>
        <source>Drag an object or a corner of the back wall.</source>
        <translation>Ziehen Sie ein Objekt oder eine Ecke der Rückwand.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="325"/>
        <source>Click around a light; click the first point (or press Enter) to close.</source>
        <translation>Klicken Sie um eine Lampe herum; ein Klick auf den ersten Punkt (oder Eingabe) schließt den Umriss.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="327"/>
        <source>Now drag a box around the window the sunlight comes through.</source>
        <translation>Ziehen Sie nun einen Rahmen um das Fenster, durch das die Sonne scheint.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="328"/>
        <source>Drag a box around the patch of sunlight.</source>
        <translation>Ziehen Sie einen Rahmen um den Sonnenfleck.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="331"/>
        <source>Click the floor straight below the first point of the outline.</source>
        <translation>Klicken Sie auf den Boden genau unter dem ersten Punkt des Umrisses.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="332"/>
        <source>Click around the top of a table or step; click the first point to close.</source>
        <translation>Klicken Sie um eine Tischplatte oder Stufe herum; ein Klick auf den ersten Punkt schließt den Umriss.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="334"/>
        <source>Left drag over the thing in front, right drag over what is behind it; Enter starts another occluder.</source>
        <translation>Mit links über das ziehen, was davor ist, mit rechts über das, was dahinter ist; Eingabe beginnt einen weiteren Verdecker.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="339"/>
        <source>Drag along an edge that runs in the %1 direction (keys X, Y, Z choose it).</source>
        <translation>Ziehen Sie entlang einer Kante in %1-Richtung (die Tasten X, Y, Z wählen sie).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="340"/>
        <source>Now drag along a second edge in the %1 direction.</source>
        <translation>Ziehen Sie nun entlang einer zweiten Kante in %1-Richtung.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="433"/>
        <source>Back wall (yours)</source>
        <translation>Rückwand (Ihre)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="433"/>
        <source>Back wall (estimated)</source>
        <translation>Rückwand (geschätzt)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="491"/>
        <source>%1 px</source>
        <translation>%1 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="529"/>
        <source>%1: %2 px</source>
        <translation>%1: %2 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="558"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="572"/>
        <source>Shaft %1</source>
        <translation>Sonnenstrahl %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="587"/>
        <source>Surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="646"/>
        <source>%1 hidden</source>
        <translation>%1 ausgeblendet</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="738"/>
        <source>Preparing the scene…</source>
        <translation>Szene wird vorbereitet …</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="741"/>
        <source>The scene could not be prepared: %1</source>
        <translation>Die Szene konnte nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="745"/>
        <source>Open a scene or a photo (File menu).</source>
        <translation>Öffnen Sie eine Szene oder ein Foto (Menü Datei).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="748"/>
        <source>Before: the photo without objects</source>
        <translation>Vorher: das Foto ohne Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="766"/>
        <source>Vanishing points: x %1, y %2, z %3 (confidence)</source>
        <translation>Fluchtpunkte: x %1, y %2, z %3 (Konfidenz)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="770"/>
        <source>Focal length %1 px (%2–%3 px)</source>
        <translation>Brennweite %1 px (%2–%3 px)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="815"/>
        <source>Before</source>
        <translation>Vorher</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="815"/>
        <source>After</source>
        <translation>Nachher</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="899"/>
        <source>the left wall</source>
        <translation>der linken Wand</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="900"/>
        <source>the right wall</source>
        <translation>der rechten Wand</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="901"/>
        <source>the back wall</source>
        <translation>der Rückwand</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="902"/>
        <source>the wall behind the camera</source>
        <translation>der Wand hinter der Kamera</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="903"/>
        <source>Its back against %1 (hold Shift to place it freely).</source>
        <translation>Mit dem Rücken an %1 (Umschalt gedrückt halten: frei platzieren).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="923"/>
        <source>Turned %1°</source>
        <translation>Gedreht auf %1°</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="933"/>
        <source>Height %1 m</source>
        <translation>Höhe %1 m</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="969"/>
        <source>An outline needs at least three points.</source>
        <translation>Ein Umriss braucht mindestens drei Punkte.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="892"/>
        <location filename="../app/studio/viewport.cpp" line="1295"/>
        <source>Cannot place the object here: %1</source>
        <translation>Das Objekt kann hier nicht stehen: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1227"/>
        <source>Each line must be at least two pixels long.</source>
        <translation>Jede Linie muss mindestens zwei Pixel lang sein.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/studio/main.cpp" line="49"/>
        <source>Insert synthetic objects into a photograph.</source>
        <translation>Synthetische Objekte in ein Foto einfügen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="54"/>
        <source>A scene file (.json) or a photo; none: the example.</source>
        <translation>Eine Szenendatei (.json) oder ein Foto; ohne Angabe: das Beispiel.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="58"/>
        <source>Grab the window to &lt;file&gt; once rendered, then exit.</source>
        <translation>Das Fenster nach dem Rendern in &lt;file&gt; speichern, dann beenden.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="62"/>
        <source>Samples per pixel to wait for (default 4).</source>
        <translation>Abzuwartende Samples pro Pixel (Vorgabe 4).</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="66"/>
        <source>Restore unsaved work left by a crash without asking.</source>
        <translation>Ungesicherte Arbeit nach einem Absturz ohne Nachfrage wiederherstellen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="69"/>
        <source>Insert the model &lt;file&gt; into the scene once it is prepared.</source>
        <translation>Das Modell &lt;file&gt; in die Szene einfügen, sobald sie vorbereitet ist.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="86"/>
        <source>Give at most one file.</source>
        <translation>Geben Sie höchstens eine Datei an.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="93"/>
        <source>expected a number &gt;= 0</source>
        <translation>eine Zahl &gt;= 0 erwartet</translation>
    </message>
</context>
</TS>
