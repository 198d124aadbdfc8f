<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>inlay::studio::Autosaver</name>
    <message>
        <location filename="../app/studio/autosave.cpp" line="77"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1 : écriture impossible (%2)</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Document</name>
    <message>
        <location filename="../app/studio/document.cpp" line="290"/>
        <location filename="../app/studio/document.cpp" line="308"/>
        <source>Preparation was cancelled.</source>
        <translation>La préparation a été annulée.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="344"/>
        <location filename="../app/studio/document.cpp" line="572"/>
        <source>The position is not a number.</source>
        <translation>La position n&apos;est pas un nombre.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="346"/>
        <location filename="../app/studio/document.cpp" line="417"/>
        <source>The height must be greater than zero.</source>
        <translation>La hauteur doit être supérieure à zéro.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="368"/>
        <source>Move object %1</source>
        <translation>Déplacer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="375"/>
        <source>Change height of object %1</source>
        <translation>Changer la hauteur de l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="382"/>
        <source>Turn object %1</source>
        <translation>Tourner l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="389"/>
        <source>Change material of object %1</source>
        <translation>Changer le matériau de l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="404"/>
        <source>There is no object %1.</source>
        <translation>Il n&apos;y a pas d&apos;objet %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="405"/>
        <source>The scene is still being prepared.</source>
        <translation>La scène est encore en préparation.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="406"/>
        <source>The scene could not be prepared.</source>
        <translation>La scène n&apos;a pas pu être préparée.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="428"/>
        <source>Insert object %1</source>
        <translation>Insérer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="440"/>
        <source>Delete object %1</source>
        <translation>Supprimer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="537"/>
        <source>Open a photo first.</source>
        <translation>Ouvrez d&apos;abord une photo.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="557"/>
        <source>There is no estimated box yet.</source>
        <translation>Il n&apos;y a pas encore de pièce estimée.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="562"/>
        <source>Accept the estimated box</source>
        <translation>Accepter la pièce estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="568"/>
        <source>There is no such corner of the back wall.</source>
        <translation>Ce coin du mur du fond n&apos;existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="578"/>
        <source>Move a corner of the back wall</source>
        <translation>Déplacer un coin du mur du fond</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="584"/>
        <source>Estimate the box again</source>
        <translation>Estimer à nouveau la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="589"/>
        <source>A light&apos;s outline needs at least three points around an area.</source>
        <translation>Le contour d&apos;une lampe doit compter au moins trois points entourant une surface.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="597"/>
        <source>Outline light %1</source>
        <translation>Détourer la lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="603"/>
        <source>Each box of a shaft must be at least two pixels wide and high.</source>
        <translation>Chaque cadre d&apos;un rayon de soleil doit mesurer au moins deux pixels de large et de haut.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="611"/>
        <source>Add shaft %1</source>
        <translation>Ajouter le rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="618"/>
        <source>A surface&apos;s outline needs at least three points around an area.</source>
        <translation>Le contour d&apos;une surface doit compter au moins trois points entourant une aire.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="627"/>
        <source>Add surface %1</source>
        <translation>Ajouter la surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="638"/>
        <source>An occluder needs a stroke over the thing in front and one over what is behind it.</source>
        <translation>Un masque d&apos;avant-plan demande un trait sur ce qui est devant et un sur ce qui est derrière.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="643"/>
        <source>Add occluder %1</source>
        <translation>Ajouter le masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="650"/>
        <source>There is no such occluder, or the stroke is empty.</source>
        <translation>Ce masque d&apos;avant-plan n&apos;existe pas, ou le trait est vide.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="656"/>
        <source>Add a stroke to occluder %1</source>
        <translation>Ajouter un trait au masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="667"/>
        <source>There is no such mark.</source>
        <translation>Ce repère n&apos;existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="674"/>
        <source>Delete light %1</source>
        <translation>Supprimer la lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="675"/>
        <source>Delete shaft %1</source>
        <translation>Supprimer le rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="676"/>
        <source>Delete surface %1</source>
        <translation>Supprimer la surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="677"/>
        <source>Delete occluder %1</source>
        <translation>Supprimer le masque d&apos;avant-plan %1</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LayersDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="140"/>
        <source>Layers</source>
        <translation>Calques</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="142"/>
        <source>Composite</source>
        <translation>Composition</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="142"/>
        <source>Photo</source>
        <translation>Photo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="143"/>
        <source>Albedo</source>
        <translation>Albédo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="143"/>
        <source>Direct light</source>
        <translation>Lumière directe</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="144"/>
        <source>With objects</source>
        <translation>Avec les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="144"/>
        <source>Without objects</source>
        <translation>Sans les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="145"/>
        <source>Mask</source>
        <translation>Masque</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="145"/>
        <source>Difference</source>
        <translation>Différence</translation>
    </message>
</context>
<context>
    <name>inlay::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="80"/>
        <source>Reading the photo</source>
        <translation>Lecture de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="81"/>
        <source>Estimating the camera</source>
        <translation>Estimation de l&apos;appareil photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="82"/>
        <source>Fitting the room</source>
        <translation>Ajustement de la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="83"/>
        <source>Estimating the lighting</source>
        <translation>Estimation de l&apos;éclairage</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="84"/>
        <source>Placing the objects</source>
        <translation>Placement des objets</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="116"/>
        <source>Samples per pixel of the shown composite</source>
        <translation>Échantillons par pixel de la composition affichée</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="117"/>
        <source>Samples per second of the renderer (millions)</source>
        <translation>Échantillons par seconde du rendu (millions)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="118"/>
        <source>Estimated error (RMSE in sRGB) where the objects change the photo</source>
        <translation>Erreur estimée (RMSE en sRGB) là où les objets modifient la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="119"/>
        <source>Render time since the last change</source>
        <translation>Temps de rendu depuis la dernière modification</translation>
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
        <translation>Préparation de la scène : %1…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="162"/>
        <source>&amp;Open Scene…</source>
        <translation>&amp;Ouvrir une scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="164"/>
        <source>Open a scene file (.json)</source>
        <translation>Ouvrir un fichier de scène (.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="167"/>
        <source>Open &amp;Photo…</source>
        <translation>Ouvrir une &amp;photo…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="169"/>
        <source>Start a new scene from a photo</source>
        <translation>Commencer une nouvelle scène à partir d&apos;une photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="172"/>
        <source>Open &amp;Example</source>
        <translation>Ouvrir l&apos;&amp;exemple</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="175"/>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="179"/>
        <source>Save &amp;As…</source>
        <translation>Enregistrer &amp;sous…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="183"/>
        <source>&amp;Export Composite…</source>
        <translation>E&amp;xporter la composition…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="185"/>
        <source>Write the current composite as PNG, JPEG, TIFF or EXR</source>
        <translation>Écrire la composition actuelle en PNG, JPEG, TIFF ou EXR</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="188"/>
        <source>Export Shown &amp;Layer…</source>
        <translation>Exporter le &amp;calque affiché…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="189"/>
        <source>Write the layer the viewport shows (albedo, mask, …) as an 8-bit image</source>
        <translation>Écrire le calque affiché (albédo, masque, …) en image 8 bits</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="191"/>
        <source>Export Scene as &amp;glTF…</source>
        <translation>Exporter la scène en &amp;glTF…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="192"/>
        <source>Write the room, its lights, the camera and the objects as glTF 2.0, to go on in Blender</source>
        <translation>Écrire la pièce, ses lumières, la caméra et les objets en glTF 2.0, pour continuer dans Blender</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="195"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="199"/>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="202"/>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="206"/>
        <source>Insert &amp;Sphere</source>
        <translation>Insérer une &amp;sphère</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="207"/>
        <source>Stand a sphere on the floor in the middle of the photo</source>
        <translation>Poser une sphère sur le sol au milieu de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="210"/>
        <source>Insert &amp;Cube</source>
        <translation>Insérer un &amp;cube</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="211"/>
        <source>Stand a cube on the floor in the middle of the photo</source>
        <translation>Poser un cube sur le sol au milieu de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="214"/>
        <source>&amp;Delete</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="215"/>
        <source>Delete the selected object or mark</source>
        <translation>Supprimer l&apos;objet ou le repère sélectionné</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="219"/>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;avant</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="222"/>
        <source>Zoom &amp;Out</source>
        <translation>Zoom a&amp;rrière</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="225"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Ajuster à la fenêtre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="228"/>
        <source>&amp;Before (Photo Only)</source>
        <translation>&amp;Avant (photo seule)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="231"/>
        <source>Toggle between the photo and the composite with the objects</source>
        <translation>Basculer entre la photo et la composition avec les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="234"/>
        <source>&amp;Accept Estimated Box</source>
        <translation>Accepter la &amp;pièce estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="235"/>
        <source>Keep the estimated back wall as yours</source>
        <translation>Garder le mur du fond estimé comme le vôtre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="240"/>
        <source>Estimate the &amp;Box Again</source>
        <translation>Estimer à nouveau la &amp;pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="241"/>
        <source>Forget your corners of the back wall</source>
        <translation>Oublier vos coins du mur du fond</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="246"/>
        <source>&amp;Prepare the Scene Again</source>
        <translation>P&amp;réparer à nouveau la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="248"/>
        <source>Estimate the camera, room and lighting again (after a cancel)</source>
        <translation>Estimer à nouveau l&apos;appareil photo, la pièce et l&apos;éclairage (après une annulation)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="250"/>
        <source>&amp;Vanishing Lines and Confidence</source>
        <translation>Lignes de &amp;fuite et confiance</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="257"/>
        <source>&amp;Select and Move</source>
        <translation>&amp;Sélectionner et déplacer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="258"/>
        <source>Outline a &amp;Light</source>
        <translation>Détourer une &amp;lampe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="259"/>
        <source>Sun &amp;Shaft</source>
        <translation>Rayon de &amp;soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="260"/>
        <source>&amp;Table Top or Step</source>
        <translation>Dessus de &amp;table ou marche</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="261"/>
        <source>&amp;Occluder Strokes</source>
        <translation>Traits de masque d&apos;&amp;avant-plan</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="271"/>
        <source>&amp;About Inlay</source>
        <translation>À &amp;propos d’Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="276"/>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="280"/>
        <source>Open &amp;Recent</source>
        <translation>Ouvrir un fichier &amp;récent</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="292"/>
        <source>&amp;Edit</source>
        <translation>&amp;Édition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="304"/>
        <source>&amp;Tools</source>
        <translation>&amp;Outils</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="307"/>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="319"/>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="323"/>
        <source>System Default</source>
        <translation>Langue du système</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="334"/>
        <source>&amp;Help</source>
        <translation>A&amp;ide</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="337"/>
        <source>Main</source>
        <translation>Principale</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="357"/>
        <location filename="../app/studio/main_window.cpp" line="366"/>
        <source>Preparing the scene…</source>
        <translation>Préparation de la scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="357"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
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
        <translation>La scène n&apos;a pas pu être préparée</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/main_window.cpp" line="391"/>
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (et %n autre)</numerusform>
            <numerusform>%1 (et %n autres)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="418"/>
        <source>– spp</source>
        <translation>– éch./px</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="419"/>
        <location filename="../app/studio/main_window.cpp" line="431"/>
        <source>– samples/s</source>
        <translation>– éch./s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="420"/>
        <source>error –</source>
        <translation>erreur –</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="421"/>
        <source>– s</source>
        <translation>– s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="425"/>
        <source>preview 1/%1</source>
        <translation>aperçu 1/%1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="426"/>
        <source>%1 spp, done</source>
        <translation>%1 éch./px, terminé</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="427"/>
        <source>%1 spp</source>
        <translation>%1 éch./px</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="428"/>
        <source>error %1</source>
        <translation>erreur %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="430"/>
        <source>%1 M samples/s</source>
        <translation>%1 M éch./s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="432"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="442"/>
        <source>%1 (new scene)</source>
        <translation>%1 (nouvelle scène)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="445"/>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="446"/>
        <source>%1[*] — Inlay</source>
        <translation>%1[*] — Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="465"/>
        <source>Cannot open</source>
        <translation>Ouverture impossible</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="465"/>
        <source>%1: no such file</source>
        <translation>%1 : fichier introuvable</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="471"/>
        <source>Cannot open the scene</source>
        <translation>Impossible d&apos;ouvrir la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="490"/>
        <location filename="../app/studio/main_window.cpp" line="500"/>
        <source>Cannot open the example</source>
        <translation>Impossible d&apos;ouvrir l&apos;exemple</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="490"/>
        <source>The example scene is not installed.</source>
        <translation>La scène d&apos;exemple n&apos;est pas installée.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="500"/>
        <source>Cannot write %1</source>
        <translation>Impossible d&apos;écrire %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="510"/>
        <source>Open Scene</source>
        <translation>Ouvrir une scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="511"/>
        <source>Inlay scenes (*.json);;All files (*)</source>
        <translation>Scènes Inlay (*.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="518"/>
        <source>Open Photo</source>
        <translation>Ouvrir une photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="519"/>
        <source>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;All files (*)</source>
        <translation>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="526"/>
        <source>Cannot save the scene</source>
        <translation>Impossible d&apos;enregistrer la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="530"/>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="545"/>
        <source>Save Scene As</source>
        <translation>Enregistrer la scène sous</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="546"/>
        <source>Inlay scenes (*.json)</source>
        <translation>Scènes Inlay (*.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="554"/>
        <location filename="../app/studio/main_window.cpp" line="575"/>
        <location filename="../app/studio/main_window.cpp" line="604"/>
        <location filename="../app/studio/main_window.cpp" line="633"/>
        <source>Nothing to export</source>
        <translation>Rien à exporter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="554"/>
        <location filename="../app/studio/main_window.cpp" line="575"/>
        <source>The composite has not been rendered yet.</source>
        <translation>La composition n&apos;a pas encore été rendue.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="558"/>
        <location filename="../app/studio/main_window.cpp" line="622"/>
        <source>PNG image (*.png)</source>
        <translation>Image PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="558"/>
        <location filename="../app/studio/main_window.cpp" line="622"/>
        <source>JPEG image (*.jpg *.jpeg)</source>
        <translation>Image JPEG (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="559"/>
        <location filename="../app/studio/main_window.cpp" line="623"/>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>Image TIFF (*.tif *.tiff)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="559"/>
        <source>OpenEXR, linear (*.exr)</source>
        <translation>OpenEXR, linéaire (*.exr)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="560"/>
        <source>Export Composite</source>
        <translation>Exporter la composition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="580"/>
        <source>Cannot export the composite</source>
        <translation>Impossible d&apos;exporter la composition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="583"/>
        <source>Exported %1 (%2 spp)</source>
        <translation>%1 exporté (%2 éch./px)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="592"/>
        <source>glTF 2.0, separate files (*.gltf)</source>
        <translation>glTF 2.0, fichiers séparés (*.gltf)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="592"/>
        <source>glTF 2.0, binary (*.glb)</source>
        <translation>glTF 2.0, binaire (*.glb)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="593"/>
        <source>Export Scene as glTF</source>
        <translation>Exporter la scène en glTF</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="604"/>
        <source>The scene is not prepared yet.</source>
        <translation>La scène n’est pas encore préparée.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="610"/>
        <source>Cannot export the scene</source>
        <translation>Impossible d’exporter la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="621"/>
        <source>Export Shown Layer</source>
        <translation>Exporter le calque affiché</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="633"/>
        <source>This layer has not been made yet.</source>
        <translation>Ce calque n&apos;a pas encore été calculé.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="640"/>
        <source>Cannot export the layer</source>
        <translation>Impossible d&apos;exporter le calque</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="641"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1 : écriture impossible (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="613"/>
        <location filename="../app/studio/main_window.cpp" line="644"/>
        <source>Exported %1</source>
        <translation>%1 exporté</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="665"/>
        <source>About Inlay</source>
        <translation>À propos d’Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="666"/>
        <source>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Inserts synthetic objects into an ordinary photograph: a box room is fitted to the photo, its lights and reflectance are estimated, and a path tracer renders the objects into it (after Karsch et al., 2011).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Insère des objets de synthèse dans une photographie ordinaire : une pièce en forme de boîte est ajustée à la photo, ses lampes et sa réflectance sont estimées, et un lancer de chemins y rend les objets (d’après Karsch et al., 2011).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="675"/>
        <source>There is no floor in the middle of the photo to stand an object on.</source>
        <translation>Il n&apos;y a pas de sol au milieu de la photo où poser un objet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="727"/>
        <source>The language changes when Inlay is started again.</source>
        <translation>La langue change au prochain démarrage d’Inlay.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="738"/>
        <source>a new scene</source>
        <translation>une nouvelle scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="741"/>
        <source>Restore unsaved work?</source>
        <translation>Restaurer le travail non enregistré ?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="742"/>
        <source>Inlay did not close properly. Unsaved work on %1 was kept at %2. Restore it?</source>
        <translation>Inlay ne s&apos;est pas fermé correctement. Le travail non enregistré sur %1 a été conservé à %2. Le restaurer ?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="746"/>
        <source>&amp;Restore</source>
        <translation>&amp;Restaurer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="747"/>
        <source>&amp;Discard</source>
        <translation>&amp;Abandonner</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="765"/>
        <source>Cannot restore the unsaved work</source>
        <translation>Impossible de restaurer le travail non enregistré</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="769"/>
        <source>Restored the unsaved work.</source>
        <translation>Le travail non enregistré a été restauré.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="776"/>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>La scène a des modifications non enregistrées. Les enregistrer ?</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PrepareWorker</name>
    <message>
        <location filename="../app/studio/prepare_worker.cpp" line="49"/>
        <source>Internal error while preparing the scene.</source>
        <translation>Erreur interne pendant la préparation de la scène.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PropertiesDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="174"/>
        <source>Properties</source>
        <translation>Propriétés</translation>
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
        <translation>Diffus</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="199"/>
        <source>Glossy</source>
        <translation>Brillant</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="200"/>
        <source>Mirror</source>
        <translation>Miroir</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="201"/>
        <source>Metal</source>
        <translation>Métal</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="202"/>
        <source>Glass</source>
        <translation>Verre</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="203"/>
        <source>Frosted glass</source>
        <translation>Verre dépoli</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="204"/>
        <source>Emissive</source>
        <translation>Émissif</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="205"/>
        <source>From the file</source>
        <translation>Celui du fichier</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="208"/>
        <source>Reflectance of the object&apos;s surface</source>
        <translation>Réflectance de la surface de l&apos;objet</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="211"/>
        <source>Base (px):</source>
        <translation>Base (px) :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="212"/>
        <source>Height:</source>
        <translation>Hauteur :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="213"/>
        <source>Turn:</source>
        <translation>Rotation :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="214"/>
        <source>Material:</source>
        <translation>Matériau :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="215"/>
        <source>Colour:</source>
        <translation>Couleur :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="234"/>
        <source>No object selected</source>
        <translation>Aucun objet sélectionné</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="239"/>
        <source>&lt;b&gt;Object %1&lt;/b&gt; (%2)</source>
        <translation>&lt;b&gt;Objet %1&lt;/b&gt; (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="284"/>
        <source>Object colour</source>
        <translation>Couleur de l&apos;objet</translation>
    </message>
</context>
<context>
    <name>inlay::studio::SceneTreeDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="30"/>
        <source>sphere</source>
        <translation>sphère</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="31"/>
        <source>cube</source>
        <translation>cube</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="45"/>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="47"/>
        <source>Item</source>
        <translation>Élément</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="47"/>
        <source>Details</source>
        <translation>Détails</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="77"/>
        <source>Room</source>
        <translation>Pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="80"/>
        <source>%1 × %2 m, %3 m high</source>
        <translation>%1 × %2 m, %3 m de haut</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="85"/>
        <source>back wall given</source>
        <translation>mur du fond donné</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="85"/>
        <source>estimated</source>
        <translation>estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="88"/>
        <source>Lights</source>
        <translation>Lampes</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="91"/>
        <source>Light %1</source>
        <translation>Lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="92"/>
        <source>outline on the photo</source>
        <translation>contour sur la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="93"/>
        <source>rectangle in 3D</source>
        <translation>rectangle en 3D</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="107"/>
        <source>Shafts</source>
        <translation>Rayons de soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="107"/>
        <source>Shaft %1</source>
        <translation>Rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="108"/>
        <source>sunlit patch and its window</source>
        <translation>tache de soleil et sa fenêtre</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="109"/>
        <source>Surfaces</source>
        <translation>Surfaces</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="109"/>
        <source>Surface %1</source>
        <translation>Surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="111"/>
        <source>Occluders</source>
        <translation>Masques d&apos;avant-plan</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="111"/>
        <source>Occluder %1</source>
        <translation>Masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="113"/>
        <source>%1 strokes in front, %2 behind</source>
        <translation>%1 traits devant, %2 derrière</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="118"/>
        <source>Objects</source>
        <translation>Objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="122"/>
        <source>Object %1</source>
        <translation>Objet %1</translation>
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
        <translation>Faites glisser un objet ou un coin du mur du fond.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="275"/>
        <source>Click around a light; click the first point (or press Enter) to close.</source>
        <translation>Cliquez autour d’une lampe ; cliquez sur le premier point (ou appuyez sur Entrée) pour fermer.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="277"/>
        <source>Now drag a box around the window the sunlight comes through.</source>
        <translation>Tracez maintenant un cadre autour de la fenêtre par où entre le soleil.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="278"/>
        <source>Drag a box around the patch of sunlight.</source>
        <translation>Tracez un cadre autour de la tache de soleil.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="281"/>
        <source>Click the floor straight below the first point of the outline.</source>
        <translation>Cliquez sur le sol juste en dessous du premier point du contour.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="282"/>
        <source>Click around the top of a table or step; click the first point to close.</source>
        <translation>Cliquez autour du dessus d&apos;une table ou d&apos;une marche ; cliquez sur le premier point pour fermer.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="284"/>
        <source>Left drag over the thing in front, right drag over what is behind it; Enter starts another occluder.</source>
        <translation>Glissez avec le bouton gauche sur ce qui est devant, avec le droit sur ce qui est derrière ; Entrée commence un autre masque.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="355"/>
        <source>Back wall (yours)</source>
        <translation>Mur du fond (le vôtre)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="355"/>
        <source>Back wall (estimated)</source>
        <translation>Mur du fond (estimé)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="411"/>
        <source>%1 px</source>
        <translation>%1 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="439"/>
        <source>Light %1</source>
        <translation>Lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="453"/>
        <source>Shaft %1</source>
        <translation>Rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="468"/>
        <source>Surface %1</source>
        <translation>Surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="614"/>
        <source>Preparing the scene…</source>
        <translation>Préparation de la scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="617"/>
        <source>The scene could not be prepared: %1</source>
        <translation>La scène n&apos;a pas pu être préparée : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="621"/>
        <source>Open a scene or a photo (File menu).</source>
        <translation>Ouvrez une scène ou une photo (menu Fichier).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="624"/>
        <source>Before: the photo without objects</source>
        <translation>Avant : la photo sans les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="642"/>
        <source>Vanishing points: x %1, y %2, z %3 (confidence)</source>
        <translation>Points de fuite : x %1, y %2, z %3 (confiance)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="646"/>
        <source>Focal length %1 px (%2–%3 px)</source>
        <translation>Focale %1 px (%2–%3 px)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="686"/>
        <source>An outline needs at least three points.</source>
        <translation>Un contour demande au moins trois points.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="817"/>
        <location filename="../app/studio/viewport.cpp" line="919"/>
        <source>Cannot place the object here: %1</source>
        <translation>Impossible de placer l&apos;objet ici : %1</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/studio/main.cpp" line="47"/>
        <source>Insert synthetic objects into a photograph.</source>
        <translation>Insérer des objets de synthèse dans une photographie.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="52"/>
        <source>A scene file (.json) or a photo; none: the example.</source>
        <translation>Un fichier de scène (.json) ou une photo ; aucun : l&apos;exemple.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="56"/>
        <source>Grab the window to &lt;file&gt; once rendered, then exit.</source>
        <translation>Capturer la fenêtre dans &lt;file&gt; une fois rendue, puis quitter.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="60"/>
        <source>Samples per pixel to wait for (default 4).</source>
        <translation>Échantillons par pixel à attendre (4 par défaut).</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="64"/>
        <source>Restore unsaved work left by a crash without asking.</source>
        <translation>Restaurer sans demander le travail non enregistré laissé par un plantage.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="79"/>
        <source>Give at most one file.</source>
        <translation>Donnez au plus un fichier.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="86"/>
        <source>expected a number &gt;= 0</source>
        <translation>un nombre &gt;= 0 est attendu</translation>
    </message>
</context>
</TS>
